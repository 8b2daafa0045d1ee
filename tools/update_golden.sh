#!/usr/bin/env bash
# Rewrites the reference images of tests/test_cli_golden.cpp from the current build. Only for a change
# that is MEANT to change what is drawn (say which, and why, in the commit message); a refactor must
# leave them as they are. Usage: tools/update_golden.sh [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-tests}"
golden="$root/tests/data/golden"
export STIPPLE_NO_CACHE=1
"$build/stipple" render -o "$golden/default_splat.png" --width 400 --height 320 --density-path splat
"$build/stipple" render -o "$golden/default_vertex.png" --width 400 --height 320 --density-path vertex
"$build/stipple" render "$root/../shared/models/stanford-bunny.obj" -o "$golden/bunny_toon_splat.png" \
  --width 400 --height 320 --yaw 30 --pitch 10 --toon
