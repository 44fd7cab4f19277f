#!/usr/bin/env bash
# Builds the WebAssembly module of the reference (wasm/, docs/wasm.md) with Debian's emscripten:
# one JavaScript file with the module embedded, BUILD/wasm/recode-wasm.js, which the
# interactive page (`recode explain --interactive`) and the Node checks load.
#
# Usage: scripts/build-wasm.sh [BUILD]        (default BUILD: build-wasm beside the sources)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build-wasm}
if ! command -v emcmake >/dev/null; then
  echo "build-wasm: emscripten is not installed (apt-get install emscripten, or scripts/setup.sh)" >&2
  exit 2
fi
# Debian's emscripten runs its optimizer under Node with the acorn parser from Debian's own
# Node modules, which Node finds only through NODE_PATH.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
emcmake cmake -S "$root" -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRECODE_WERROR=ON >/dev/null
cmake --build "$out" --target recode_wasm
echo "build-wasm: $out/wasm/recode-wasm.js"
