#!/usr/bin/env bash
# Installs the Debian packages the build, the tests and the tools need.
# Idempotent: when everything is present it only checks with dpkg and returns.
#
#   scripts/setup.sh            every package (scripts/test.sh, CI)
#   scripts/setup.sh --demo     only what `scripts/build.sh --demo` needs: the compiler, CMake,
#                               Ninja and the libraries of the `recode` program without its
#                               optional devices, oracles and peers (scripts/demo.sh)
set -euo pipefail

# The `recode` program alone: every library it needs that has no option to leave it out.
demo_packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libstb-dev
  libtbb-dev libhwy-dev
)
# The rest: the tests (with CGAL's demo meshes), the PLY reader (assimp), the oracles, the GPU
# devices, the peers, the WebAssembly module and browser checks, the Python module, the sanitizer
# and fuzzing builds, the docs; the compiler cache (scripts/build.sh).
packages=(
  "${demo_packages[@]}" clang-format ccache
  catch2 libbenchmark-dev
  libassimp-dev libcgal-demo
  libembree-dev libcgal-dev libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libvulkan-dev mesa-vulkan-drivers glslang-tools vulkan-validationlayers
  clang-14 libfuzzer-14-dev
  libfcl-dev libbullet-dev gnuplot-nox
  chromium python3-websocket emscripten
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed doxygen
  python3-venv python3-pip python3-setuptools python3-wheel mypy
  git bc
)
case "${1:-}" in
  "") ;;
  --demo) packages=("${demo_packages[@]}") ;;
  *) echo "usage: scripts/setup.sh [--demo]" >&2; exit 2 ;;
esac

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
