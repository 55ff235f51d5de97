#!/usr/bin/env bash
# Installs every system package manylights needs to build, test and render headless.
# Idempotent: packages already present are not touched, and apt is only called when
# something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libgbm1
  libglfw3-dev libx11-dev libglm-dev nlohmann-json3-dev libstb-dev libtinyobjloader-dev
  libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
  libimgui-dev xvfb xauth imagemagick ffmpeg
  libtinygltf-dev assimp-testmodels clang libclang-rt-dev clang-format
  libopenexr-dev openexr glslang-tools
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
