# Sourced by the scripts under tools/: common environment for Vulkan on this machine.
# The Vulkan loader and lavapipe want a runtime folder; CI and fresh shells may not set one.
if [ -z "${XDG_RUNTIME_DIR:-}" ]; then
  export XDG_RUNTIME_DIR="/tmp/stipple-runtime-$(id -u)"
  mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
fi
STIPPLE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
STIPPLE_JOBS="${STIPPLE_JOBS:-$(nproc)}"
