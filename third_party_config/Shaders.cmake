# Compiles every shaders/<name>.<stage> file to <build>/shaders/<name>.<stage>.spv with glslang.
# Shaders are loaded by name at run time (see src/gpu/shaders.cpp).
set(STIPPLE_SHADER_OUTPUT_DIR ${CMAKE_BINARY_DIR}/shaders)
file(GLOB STIPPLE_SHADER_SOURCES CONFIGURE_DEPENDS
  ${CMAKE_SOURCE_DIR}/shaders/*.vert ${CMAKE_SOURCE_DIR}/shaders/*.frag ${CMAKE_SOURCE_DIR}/shaders/*.comp
  ${CMAKE_SOURCE_DIR}/shaders/*.geom)
file(GLOB STIPPLE_SHADER_INCLUDES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*.h ${CMAKE_SOURCE_DIR}/shaders/*.glsl)
set(STIPPLE_SPIRV_OUTPUTS)
foreach(shader ${STIPPLE_SHADER_SOURCES})
  get_filename_component(name ${shader} NAME)
  set(spv ${STIPPLE_SHADER_OUTPUT_DIR}/${name}.spv)
  add_custom_command(
    OUTPUT ${spv}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${STIPPLE_SHADER_OUTPUT_DIR}
    COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 -I${CMAKE_SOURCE_DIR}/shaders -I${CMAKE_SOURCE_DIR}/src -o ${spv} ${shader}
    DEPENDS ${shader} ${STIPPLE_SHADER_INCLUDES}
    COMMENT "glslang ${name}"
    VERBATIM)
  list(APPEND STIPPLE_SPIRV_OUTPUTS ${spv})
endforeach()
add_custom_target(stipple_shaders ALL DEPENDS ${STIPPLE_SPIRV_OUTPUTS})
