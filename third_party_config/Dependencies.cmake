# Every dependency comes from a Debian 12 package; third_party_config/install_deps.sh installs them.
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
find_package(Vulkan REQUIRED)
find_package(glm REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(glfw3 REQUIRED)
find_package(meshoptimizer REQUIRED)
find_package(PkgConfig REQUIRED)
find_package(nanoflann REQUIRED)                        # libnanoflann-dev: k-d tree for the plotter order
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)  # libzstd-dev: the stipple cache's entries
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)  # libcairo2-dev: PDF export
find_package(tinyxml2 REQUIRED)                         # libtinyxml2-dev: the export tests parse the SVG

# stb is header-only in Debian (libstb-dev) with only a pkg-config file.
if(NOT TARGET stb::stb)
  add_library(stb::stb INTERFACE IMPORTED)
  set_target_properties(stb::stb PROPERTIES INTERFACE_INCLUDE_DIRECTORIES /usr/include/stb)
endif()


find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
