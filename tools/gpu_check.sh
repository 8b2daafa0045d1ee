#!/bin/bash
# The checks that need a real GPU (issue 17), on a machine that has one and lavapipe beside it:
#   1. every density path, every line kind, the default scene and the animated models drawn on the GPU
#      with the validation layer on (a validation message fails the render);
#   2. `stipple parity`: lavapipe and the GPU draw the same stipples (counts within 0.1%, ink within 1%);
#   3. `stipple bench` on the GPU (frames queued 8 per submission, its default on a GPU).
# Usage: tools/gpu_check.sh [OUT_DIR]   (default: gpu-check). STIPPLE=path/to/stipple (default:
# build-release/stipple); the models come from $STIPPLE_SHARED_MODELS or ../shared/models.
# Exit status: the number of steps that failed (0: all passed). Every step's output goes to OUT_DIR/log.txt.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-gpu-check}
stipple=${STIPPLE:-$root/build-release/stipple}
models=${STIPPLE_SHARED_MODELS:-$root/../shared/models}
mkdir -p "$out/images"
log=$out/log.txt
: >"$log"
start=$(date +%s)
failures=0
say() { echo "[$(($(date +%s) - start))s] $*" | tee -a "$log"; }
step() {  # step SECONDS COMMAND...: runs it with a time limit, logs it, counts a failure
    local limit=$1
    shift
    say "RUN $*"
    timeout "$limit" "$@" >>"$log" 2>&1
    local rc=$?
    say "rc=$rc"
    [ $rc -eq 0 ] || failures=$((failures + 1))
}

"$stipple" render --list-devices | tee -a "$log"
gpu=$("$stipple" render --list-devices 2>/dev/null | grep -v "(CPU)" | head -1 | cut -d: -f1)
cpu=$("$stipple" render --list-devices 2>/dev/null | grep "(CPU)" | head -1 | cut -d: -f1)
if [ -z "$gpu" ]; then
    say "no GPU among the Vulkan devices: nothing to check"
    exit 1
fi
say "GPU: device $gpu; lavapipe: device ${cpu:-none}"

# 1. Validation on the GPU.
export STIPPLE_VALIDATION=1
bunny=$models/stanford-bunny.obj
for path in splat vertex indirect cpu cpu-splat; do
    step 120 "$stipple" render "$bunny" --device "$gpu" --density-path $path --yaw 30 --pitch 15 --stats \
        -o "$out/images/bunny_$path.png"
done
step 120 "$stipple" render --device "$gpu" --stats -o "$out/images/default.png"
step 120 "$stipple" render "$models/ogre.obj" --device "$gpu" --silhouette-lines --contours --borders --creases \
    --stats -o "$out/images/ogre_lines.png"
step 120 "$stipple" render "$models/fox.glb" --device "$gpu" --animation Run --time 0.4 --contours --stats \
    -o "$out/images/fox_run.png"
step 120 "$stipple" render "$models/AnimatedMorphCube.gltf" --device "$gpu" --time 0.5 --stats -o "$out/images/morph.png"
step 120 "$stipple" render "$models/horse.ply" --device "$gpu" --up z --point-size 8 --dmax 0.02 --stats \
    -o "$out/images/horse_large_dots.png"
step 180 "$stipple" render "$models/igea.ply" --device "$gpu" --width 8000 --height 6000 --stats -o "$out/igea_8000.png"
unset STIPPLE_VALIDATION

# 2. Parity: lavapipe against the GPU.
if [ -n "$cpu" ]; then
    for model in stanford-bunny.obj fox.glb horse.ply spot.obj ogre.obj; do
        step 180 "$stipple" parity "$models/$model" --devices "$gpu,$cpu" --paths splat,vertex,indirect
    done
    step 180 "$stipple" parity --devices "$gpu,$cpu" --paths splat,vertex,indirect
else
    say "no lavapipe device: parity skipped"
fi

# 3. The bench.
step 600 "$stipple" bench --device "$gpu" --out "$out/bench"
say "done: $failures step(s) failed"
exit $failures
