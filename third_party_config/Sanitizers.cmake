# STIPPLE_SANITIZE: everything built under AddressSanitizer and UndefinedBehaviorSanitizer, stopping at
# the first report of either (tools/run_sanitized_tests.sh runs the test suite this way, with the
# suppressions of tests/sanitizers/ for what the Vulkan loader and lavapipe do, never for our code).
# STIPPLE_FUZZ: also the libFuzzer harnesses of tests/fuzz (clang only; tools/run_fuzzers.sh).
option(STIPPLE_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(STIPPLE_FUZZ "Build the libFuzzer harnesses under tests/fuzz (needs clang and STIPPLE_SANITIZE)" OFF)

if(STIPPLE_SANITIZE)
  # Frame pointers keep the reports' stacks whole; -fno-sanitize-recover makes every UBSan finding fatal.
  set(STIPPLE_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_compile_options(${STIPPLE_SANITIZE_FLAGS})
  add_link_options(${STIPPLE_SANITIZE_FLAGS})
endif()

if(STIPPLE_FUZZ)
  if(NOT STIPPLE_SANITIZE OR NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "STIPPLE_FUZZ needs clang (e.g. -DCMAKE_CXX_COMPILER=clang++-15) and -DSTIPPLE_SANITIZE=ON")
  endif()
endif()

if(STIPPLE_SANITIZE)
  # Keeps lavapipe and the validation layer mapped in sanitized processes (see the source's comment).
  add_library(stipple_keep_loaded SHARED ${CMAKE_SOURCE_DIR}/tests/sanitizers/keep_loaded.c)
  target_compile_options(stipple_keep_loaded PRIVATE -fno-sanitize=all)
  target_link_options(stipple_keep_loaded PRIVATE -fno-sanitize=all)
  target_link_libraries(stipple_keep_loaded PRIVATE ${CMAKE_DL_LIBS})
endif()
