# Every dependency comes from a Debian 12 package; third_party_config/install_deps.sh installs them.
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
find_package(Vulkan REQUIRED)
find_package(glm REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(glfw3 REQUIRED)
find_package(meshoptimizer REQUIRED)
find_package(PkgConfig REQUIRED)

# stb is header-only in Debian (libstb-dev) with only a pkg-config file.
if(NOT TARGET stb::stb)
  add_library(stb::stb INTERFACE IMPORTED)
  set_target_properties(stb::stb PROPERTIES INTERFACE_INCLUDE_DIRECTORIES /usr/include/stb)
endif()


find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
