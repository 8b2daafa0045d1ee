# libdraco (Debian's libdraco-dev) isolated: it carries its own, older tinygltf and stb_image_write and
# exports them, so linked as it is it took calls meant for libtinygltf (a tinygltf::Model of the other
# layout, freed as garbage) or clashed with our stb. Each half of src/mesh/draco_codec.h is linked with
# libdraco.a into one relocatable object (ld -r takes only the archive members it needs), and every symbol
# of that object but the interface's is made local, so nothing else can bind to it (draco/isolate.sh).
find_package(draco REQUIRED)
include(CMakeParseArguments)
# GNU binutils whatever the compiler (lld has no --force-group-allocation); build-essential brings them.
find_program(STIPPLE_GNU_LD NAMES ld.bfd ld REQUIRED)
find_program(STIPPLE_GNU_OBJCOPY NAMES objcopy REQUIRED)
find_program(STIPPLE_GNU_NM NAMES nm REQUIRED)

# stipple_isolated_draco(<target> SOURCE <file> SYMBOLS <extern "C" names...>): a static library <target>
# holding the isolated object.
function(stipple_isolated_draco target)
  cmake_parse_arguments(ARG "" "SOURCE" "SYMBOLS" ${ARGN})
  add_library(${target}_code OBJECT ${ARG_SOURCE})
  target_include_directories(${target}_code PRIVATE ${CMAKE_SOURCE_DIR}/src)
  target_include_directories(${target}_code SYSTEM PRIVATE $<TARGET_PROPERTY:draco::draco_static,INTERFACE_INCLUDE_DIRECTORIES>)
  set_target_properties(${target}_code PROPERTIES POSITION_INDEPENDENT_CODE ON)
  set(object ${CMAKE_CURRENT_BINARY_DIR}/${target}.o)
  add_custom_command(
    OUTPUT ${object}
    COMMAND ${CMAKE_SOURCE_DIR}/third_party_config/draco/isolate.sh ${STIPPLE_GNU_LD} ${STIPPLE_GNU_OBJCOPY} ${STIPPLE_GNU_NM} ${object}
            $<TARGET_FILE:draco::draco_static> $<TARGET_OBJECTS:${target}_code> -- ${ARG_SYMBOLS}
    DEPENDS ${target}_code $<TARGET_OBJECTS:${target}_code> ${CMAKE_SOURCE_DIR}/third_party_config/draco/isolate.sh
    COMMENT "Isolating libdraco in ${target}.o"
    COMMAND_EXPAND_LISTS VERBATIM)
  add_library(${target} STATIC ${object})
  set_target_properties(${target} PROPERTIES LINKER_LANGUAGE CXX)
endfunction()

stipple_isolated_draco(stipple_draco_decode SOURCE ${CMAKE_SOURCE_DIR}/third_party_config/draco/draco_decode.cpp
                       SYMBOLS stipple_draco_decode stipple_draco_free)
stipple_isolated_draco(stipple_draco_encode SOURCE ${CMAKE_SOURCE_DIR}/third_party_config/draco/draco_encode.cpp
                       SYMBOLS stipple_draco_encode stipple_draco_free_bytes)
