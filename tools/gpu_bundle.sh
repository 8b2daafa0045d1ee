#!/bin/bash
# Packs the built stipple, its shared libraries, lavapipe, the validation layer and the shared models into
# one archive, for a machine with a GPU but none of the Debian packages (a CUDA image, say), and writes the
# script that runs the GPU checks there in a time budget (validation renders on every path and line kind,
# the bench, then lavapipe/GPU parity while time is left; tools/gpu_check.sh is the unhurried version).
# Usage: tools/gpu_bundle.sh [OUT_DIR]   (default .gl, which .gitignore ignores)
# There: mkdir -p /opt && tar -C /opt -xJf OUT_DIR/bundle.tar.xz && OUT=results bash OUT_DIR/run.sh
# The archive is about 55 MB (libLLVM for lavapipe is most of it).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/.gl}
build=${STIPPLE_BUILD:-$root/build-release}
models=${STIPPLE_SHARED_MODELS:-$root/../shared/models}
lib=/usr/lib/x86_64-linux-gnu
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
b=$stage/bundle
mkdir -p "$out" "$b/lib" "$b/icd" "$b/layers" "$b/models" "$b/bin/shaders"
# Every library the binary, lavapipe, the validation layer and the loader need, but the C library's own.
libs=$( (ldd "$build/stipple"; ldd $lib/libvulkan_lvp.so; ldd $lib/libVkLayer_khronos_validation.so; ldd $lib/libvulkan.so.1) |
    awk '/=>/ {print $3}' | sort -u | grep -v -E '/(libc|libm|libpthread|libdl|librt|ld-linux-x86-64)\.so')
for l in $libs $lib/libvulkan.so.1 $lib/libvulkan_lvp.so $lib/libVkLayer_khronos_validation.so; do cp -L "$l" "$b/lib/"; done
for g in libGLdispatch.so.0 libGLX.so.0; do [ -e $lib/$g ] && cp -L $lib/$g "$b/lib/"; done  # for NVIDIA's ICD
cat >"$b/icd/lvp_icd.json" <<J
{ "ICD": { "api_version": "1.1.230", "library_path": "/opt/bundle/lib/libvulkan_lvp.so" }, "file_format_version": "1.0.0" }
J
sed 's#"library_path": *"[^"]*"#"library_path": "/opt/bundle/lib/libVkLayer_khronos_validation.so"#' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >"$b/layers/VkLayer_khronos_validation.json"
cp "$models"/* "$b/models/" 2>/dev/null || echo "no shared models in $models: the checks will use the default scene only"
cp "$build/stipple" "$b/bin/"
cp "$build"/shaders/*.spv "$b/bin/shaders/"
tar -C "$stage" -cf - bundle | xz -T2 -6 >"$out/bundle.tar.xz"
cat >"$out/run.sh" <<'RUN'
#!/bin/bash
# The GPU checks from /opt/bundle, logged to $OUT/log.txt (OUT: a folder; default ./gpu-results).
set -u
OUT=${OUT:-gpu-results}
mkdir -p "$OUT/img" /tmp/xdg
T0=$(date +%s)
export LD_LIBRARY_PATH=/opt/bundle/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib:${LD_LIBRARY_PATH:-}
nv=$(ls /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd*.json /etc/vulkan/icd.d/nvidia_icd*.json 2>/dev/null | head -1)
export VK_DRIVER_FILES=${nv:+$nv:}/opt/bundle/icd/lvp_icd.json
export VK_ICD_FILENAMES=$VK_DRIVER_FILES VK_LAYER_PATH=/opt/bundle/layers
export STIPPLE_SHADER_DIR=/opt/bundle/bin/shaders STIPPLE_SHARED_MODELS=/opt/bundle/models
export XDG_RUNTIME_DIR=/tmp/xdg XDG_CACHE_HOME=/tmp/stipple-cache
S=/opt/bundle/bin/stipple M=/opt/bundle/models log=$OUT/log.txt fails=0
say() { echo "[$(($(date +%s) - T0))s] $*" | tee -a "$log"; }
step() { local l=$1; shift; say "RUN $*"; timeout "$l" "$@" >>"$log" 2>&1; local rc=$?; say "rc=$rc"; [ $rc -eq 0 ] || fails=$((fails + 1)); }
say "NVIDIA ICD: ${nv:-none}"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv >>"$log" 2>&1
$S render --list-devices 2>&1 | tee -a "$log"
gpu=$($S render --list-devices 2>/dev/null | grep -v "(CPU)" | head -1 | cut -d: -f1)
cpu=$($S render --list-devices 2>/dev/null | grep "(CPU)" | head -1 | cut -d: -f1)
[ -n "$gpu" ] || { say "no GPU among the Vulkan devices"; exit 1; }
export STIPPLE_VALIDATION=1
for p in splat vertex indirect cpu cpu-splat; do
    step 90 $S render $M/stanford-bunny.obj --device $gpu --density-path $p --yaw 30 --pitch 15 --stats -o "$OUT/img/bunny_$p.png"
done
step 90 $S render --device $gpu --stats -o "$OUT/img/default.png"
step 90 $S render $M/ogre.obj --device $gpu --silhouette-lines --contours --borders --creases --stats -o "$OUT/img/ogre_lines.png"
step 90 $S render $M/fox.glb --device $gpu --animation Run --time 0.4 --contours --stats -o "$OUT/img/fox_run.png"
step 90 $S render $M/AnimatedMorphCube.gltf --device $gpu --time 0.5 --stats -o "$OUT/img/morph.png"
step 90 $S render $M/horse.ply --device $gpu --up z --point-size 8 --dmax 0.02 --stats -o "$OUT/img/horse_large_dots.png"
step 90 $S render $M/igea.ply --device $gpu --width 8000 --height 6000 --stats -o /tmp/igea_8000.png
unset STIPPLE_VALIDATION
step 260 $S bench --device $gpu --out /tmp/stipple-bench
cp /tmp/stipple-bench/results.md /tmp/stipple-bench/results.json "$OUT/" 2>/dev/null
for m in stanford-bunny.obj fox.glb ogre.obj horse.ply spot.obj ""; do
    [ $(($(date +%s) - T0)) -lt 440 ] || { say "no time left for parity ${m:-of the default scene}"; continue; }
    [ -n "$cpu" ] && step 100 $S parity ${m:+$M/$m} --devices "$gpu,$cpu" --paths splat,vertex,indirect
done
say "done: $fails step(s) failed"
(cd "$OUT" && tar -cf images.tar img && rm -rf img)
exit $fails
RUN
ls -la "$out"
