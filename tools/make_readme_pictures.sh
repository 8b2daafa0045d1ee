#!/usr/bin/env bash
# The README's pictures of vector and print output, from the project's own default scene
# (assets/blobby.glb; no shared models): the screen image, its SVG rasterised, and the plot order
# (the SVG with the pen-up moves in light red), into docs/images/.
# Usage: tools/make_readme_pictures.sh [STIPPLE_EXECUTABLE]   (default: build-release/stipple, as the README builds it)
# Needs rsvg-convert (librsvg2-bin). The same command always writes the same pictures.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$STIPPLE_ROOT"
stipple="${1:-build-release/stipple}"
[ -x "$stipple" ] || { echo "make_readme_pictures.sh: $stipple is not built (cmake --build build-release --target stipple)" >&2; exit 1; }
command -v rsvg-convert >/dev/null || { echo "make_readme_pictures.sh: rsvg-convert is missing (apt-get install librsvg2-bin)" >&2; exit 1; }
out=docs/images
mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# 640x512 px on a 160x128 mm page without margin: 4 px a mm, so the three pictures line up.
view=(--width 640 --height 512)
page=(--page 160x128mm --margin 0 --fit frame)
"$stipple" render "${view[@]}" -o "$out/default.png"
"$stipple" render "${view[@]}" "${page[@]}" --fill-paper -o "$tmp/default.svg" --stats | grep '^plot:'
rsvg-convert -w 640 -h 512 "$tmp/default.svg" -o "$out/default-svg.png"
# The plot order on fewer dots (a smaller budget), on a small page so that the 0.05 mm pen-up
# moves come out thick enough to see at 640 px.
"$stipple" render "${view[@]}" --page 40x32mm --margin 0 --fit frame --fill-paper --max-stipples 60000 --show-travel \
  -o "$tmp/travel.svg" --stats | grep '^plot:'
rsvg-convert -w 640 -h 512 "$tmp/travel.svg" -o "$out/default-travel.png"
ls -l "$out"/default.png "$out"/default-svg.png "$out"/default-travel.png
