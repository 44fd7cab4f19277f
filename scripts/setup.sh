#!/usr/bin/env bash
# Installs every Debian package the build, the tests and the tools need.
# Idempotent: when everything is present it only checks with dpkg and returns.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libeigen3-dev libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libstb-dev
  catch2 libbenchmark-dev libtbb-dev libhwy-dev
  libembree-dev libcgal-dev libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libvulkan-dev mesa-vulkan-drivers glslang-tools vulkan-validationlayers
  clang-14 libfuzzer-14-dev
  libfcl-dev libbullet-dev gnuplot-nox
  chromium python3-websocket emscripten
  pybind11-dev python3-dev python3-numpy python3-pytest doxygen
  python3-venv python3-pip python3-setuptools python3-wheel mypy
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
