#!/usr/bin/env bash
# Installs what is missing, builds stipple (Release) and renders the built-in default scene to a PNG.
# Usage: tools/render_default.sh [OUT.png] [more stipple render options]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$STIPPLE_ROOT"
third_party_config/install_deps.sh
# A fresh tree builds the program alone; a developer's existing build-release keeps its tests option
# (passing OFF there would drop the tests from the developer's next build). It is always a Release build.
tests_option=()
[ -f build-release/CMakeCache.txt ] || tests_option=(-DSTIPPLE_BUILD_TESTS=OFF)
cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release "${tests_option[@]}" >/dev/null
cmake --build build-release -j "$STIPPLE_JOBS" --target stipple
out="${1:-stipple.png}"
shift || true
./build-release/stipple render -o "$out" --stats "$@"
