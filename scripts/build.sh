#!/usr/bin/env bash
# Configures and builds the project (Release, Ninja, warnings as errors).
#
#   scripts/build.sh            everything, into ./build: the programs, the devices and oracles
#                               whose packages are found, the tests, examples, benchmarks, the
#                               Python and WebAssembly modules (scripts/test.sh)
#   scripts/build.sh --demo     the `recode` program alone, into ./build-demo, without the
#                               optional parts (GPU devices, Embree and CGAL oracles, FCL and
#                               Bullet peers, the WebAssembly module), whether or not their
#                               packages are installed: what scripts/setup.sh --demo installs
#                               suffices (scripts/demo.sh); warnings are not errors there (the
#                               full build's -Werror is for who changes the code, not for a
#                               newcomer's first run with another compiler)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
# The compiler cache, when installed (scripts/setup.sh installs it): a rebuild after a branch
# switch recompiles only what changed, and the tests that build the libraries again as a user
# would (tests/package, tests/link) find most of their objects there, since the main build's
# command lines are theirs.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
case "${1:-}" in
  "")
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DRECODE_WERROR=ON "${launcher[@]}" \
      >/dev/null
    cmake --build build -j "$jobs"
    ;;
  --demo)
    # -O1: four fifths of the compile time of Release's -O3 (the compiler's time is most of the
    # demo's wait), the same bytes out (no option here lets the compiler reorder or fuse
    # floating-point arithmetic; the raster targets keep -ffp-contract=off); the pass times it
    # prints are slower than build/'s. GCC 12 at -O1 warns of a "maybe uninitialized" vector
    # inside std::variant's move (raster/kit), which -O3 does not: not shown to a newcomer.
    cmake -S . -B build-demo -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_CXX_FLAGS=-Wno-maybe-uninitialized \
      -DRECODE_WERROR=OFF \
      -DRECODE_BUILD_TESTS=OFF -DRECODE_BUILD_BENCHMARKS=OFF -DRECODE_BUILD_EXAMPLES=OFF \
      -DRECODE_BUILD_PYTHON=OFF -DRECODE_WITH_WASM=OFF -DRECODE_WITH_EMBREE=OFF \
      -DRECODE_WITH_CGAL=OFF -DRECODE_WITH_PEERS=OFF -DRECODE_WITH_OSMESA=OFF \
      -DRECODE_WITH_EGL=OFF -DRECODE_WITH_VULKAN=OFF "${launcher[@]}" >/dev/null
    cmake --build build-demo -j "$jobs" --target recode
    ;;
  *) echo "usage: scripts/build.sh [--demo]" >&2; exit 2 ;;
esac
