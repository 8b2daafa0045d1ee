#!/usr/bin/env bash
# Installs what is missing, builds everything and runs the whole test suite under ctest, with the
# Vulkan validation layer on in every test (any validation message fails the test).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$STIPPLE_ROOT"
third_party_config/install_deps.sh
# Optimised with checks kept: the generation and rendering tests handle ~10^5-10^6 stipples.
cmake -S . -B build-tests -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-tests -j "$STIPPLE_JOBS"
export STIPPLE_VALIDATION=1
ctest --test-dir build-tests --output-on-failure -j "$STIPPLE_JOBS" --timeout 600 "$@"
