# Sourced by tools/run_sanitized_tests.sh and tools/run_fuzzers.sh: the clang-15 ASan + UBSan build
# both use (one build folder, so CI compiles the sanitized libraries once) and the runtime options
# that make every report fatal.
STIPPLE_ASAN_BUILD="${STIPPLE_ASAN_BUILD:-build-asan}"

configure_sanitized_build() {
  local launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
  # RelWithDebInfo: ~10^6-stipple tests are too slow at -O0 under ASan; -O2 keeps the checks.
  cmake -S "$STIPPLE_ROOT" -B "$STIPPLE_ASAN_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-15 -DCMAKE_CXX_COMPILER=clang++-15 "${launcher[@]}" \
    -DSTIPPLE_SANITIZE=ON -DSTIPPLE_FUZZ=ON >/dev/null
}

# Reports name functions and lines only with a symbolizer (llvm-15 from install_deps.sh).
for s in llvm-symbolizer-15 llvm-symbolizer; do
  if command -v "$s" >/dev/null; then export ASAN_SYMBOLIZER_PATH="$(command -v "$s")"; break; fi
done
supp="$STIPPLE_ROOT/tests/sanitizers"
# halt_on_error with -fno-sanitize-recover: the first report ends the process, with exit code 99 so that
# a CLI test expecting exit 1 for bad input cannot mistake a report for the clean refusal.
# Leaks are checked (LSan) with lsan.supp naming the libraries whose leaks are not ours; asan.supp
# likewise for errors the interceptors see inside those libraries.
export ASAN_OPTIONS="halt_on_error=1:exitcode=99:detect_leaks=1:strict_init_order=1:check_initialization_order=1:detect_stack_use_after_return=1:suppressions=$supp/asan.supp:print_suppressions=0"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:exitcode=99:print_stacktrace=1:suppressions=$supp/ubsan.supp:print_suppressions=0"
