#!/usr/bin/env bash
# Installs Morphogen's Debian 12 packages (only those missing) and builds it
# into build/. Idempotent: a second run installs nothing and rebuilds only
# what changed. Used by scripts/render-default.sh, scripts/test.sh and CI.
# --packages-only: install the packages, build nothing (scripts/sanitize.sh).
# --target NAME...: build only those targets (scripts/render-default.sh builds
#   the morphogen command alone, not the tests and fuzz replays).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake ninja-build g++ pkg-config python3 python3-glad
  libglfw3-dev libglm-dev libosmesa6-dev libegl-dev libgl-dev libopengl-dev libegl-mesa0
  libgl1-mesa-dri
  libopenimageio-dev libtinygltf-dev libstb-dev libeigen3-dev nlohmann-json3-dev
  libcli11-dev libgtest-dev libgmock-dev libimgui-dev libmeshoptimizer-dev
  libtinyobjloader-dev libcgal-dev
  xvfb xauth help2man
  clang libclang-rt-14-dev libfuzzer-14-dev libomp-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "==> setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "==> setup: all ${#packages[@]} Debian packages already installed"
fi

[ "${1:-}" = "--packages-only" ] && exit 0
targets=()
if [ "${1:-}" = "--target" ]; then
  shift
  targets=(--target "$@")
fi

echo "==> setup: configuring (build/)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "==> setup: building${targets[*]:+ ${targets[*]:1}}"
cmake --build build --parallel "$(nproc)" "${targets[@]}"
echo "==> setup: done"
