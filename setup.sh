#!/usr/bin/env bash
# Installs every Debian 12 package vkrt needs (idempotent; run as root or with sudo available)
# and builds the Release configuration into build/.
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libglm-dev libtinyobjloader-dev libopenimageio-dev openimageio-tools libpugixml-dev nlohmann-json3-dev libcli11-dev
  libpng-dev libxxhash-dev
  libopenmpi-dev openmpi-bin
  libcpp-httplib-dev
  libgtest-dev libgmock-dev
  gnuplot-nox
  chromium-headless-shell
  clang libclang-rt-14-dev
  python3
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build_type=${VKRT_BUILD_TYPE:-Release}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$build_type"
cmake --build build -j"$(nproc)"
