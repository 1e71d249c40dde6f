#!/usr/bin/env bash
# Installs the Debian 12 packages voxmod needs to build, test and run. Idempotent: when everything is
# present it prints nothing and exits 0. Uses sudo when not root. Nothing else is downloaded.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git clang clang-format
  # libraries
  libglm-dev libglfw3-dev libimgui-dev libstb-dev zlib1g-dev libteem-dev nlohmann-json3-dev libcli11-dev
  libassimp-dev libminizip-dev libexpat1-dev
  # ray thickness against the mesh (Embree); see docs/dependencies.md
  libembree-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # volume export: VTK image data (.vti) and OpenVDB (.vdb); see docs/dependencies.md
  libvtk9-dev libopenvdb-dev
  # voxmod batch over MPI ranks (optional at build time); see docs/dependencies.md
  libopenmpi-dev openmpi-bin
  # OpenGL / EGL (glvnd + Mesa llvmpipe); see docs/dependencies.md
  libegl-dev libopengl-dev libgl-dev libegl1 libegl-mesa0 libopengl0 libgl1 libglx-mesa0 libgl1-mesa-dri
  # window tests and screenshots
  xvfb xauth x11-apps xdotool imagemagick
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
((${#missing[@]} == 0)) && exit 0

echo "voxmod setup: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
