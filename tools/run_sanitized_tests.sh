#!/usr/bin/env bash
# Builds the whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang-15, in
# build-asan) and runs it under ctest with the Vulkan validation layer on. Any sanitizer report (ASan,
# LeakSanitizer, UBSan) ends its process with exit code 99 and so fails its test; the suppressions in
# tests/sanitizers/ cover only the Vulkan loader's and lavapipe's own code (tools/sanitizer_env.sh).
# Usage: tools/run_sanitized_tests.sh [more ctest arguments, e.g. -R Loader]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
source "$(dirname "${BASH_SOURCE[0]}")/sanitizer_env.sh"
cd "$STIPPLE_ROOT"
third_party_config/install_deps.sh
configure_sanitized_build
cmake --build "$STIPPLE_ASAN_BUILD" -j "$STIPPLE_JOBS"
export STIPPLE_VALIDATION=1
# The Vulkan loader unloads lavapipe and the validation layer when an instance is destroyed; the
# preloaded helper (tests/sanitizers/keep_loaded.c) keeps them mapped so that LeakSanitizer can name
# them and lsan.supp can suppress their leaks by library (an unloaded library's frames have no name,
# and ours must never be suppressed wholesale).
keep=()
for lib in libvulkan_lvp.so libVkLayer_khronos_validation.so; do
  path=$(find /usr/lib /usr/local/lib -name "$lib" -print -quit 2>/dev/null || true)
  if [ -n "$path" ]; then keep+=("$path"); fi
done
export STIPPLE_KEEP_LOADED="$(IFS=:; echo "${keep[*]}")"
LD_PRELOAD="$(cd "$STIPPLE_ASAN_BUILD" && pwd)/libstipple_keep_loaded.so" \
  ctest --test-dir "$STIPPLE_ASAN_BUILD" --output-on-failure -j "$STIPPLE_JOBS" --timeout 900 "$@"
