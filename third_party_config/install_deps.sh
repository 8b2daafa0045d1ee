#!/usr/bin/env bash
# Installs the Debian 12 packages that stipple's build, tests and tools need. Idempotent: packages
# already installed are skipped, and nothing is downloaded when all are present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools glslang-tools spirv-tools
  libglm-dev libglfw3-dev libx11-dev libxext-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  libimgui-dev libmeshoptimizer-dev libdraco-dev libgtest-dev
  libzstd-dev libnanoflann-dev libcairo2-dev libtinyxml2-dev poppler-utils librsvg2-bin
  xvfb xauth xdotool x11-utils
  clang-15 libfuzzer-15-dev llvm-15  # the sanitized build and the fuzzers (tools/run_sanitized_tests.sh, run_fuzzers.sh)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install_deps: done"
