#!/usr/bin/env bash
# Builds the WebAssembly decoder: web/build_wasm.sh [BUILD_DIR] (default build-wasm)
# -> samples/web/dist/hullpack_decoder_wasm.{js,wasm}. Needs emscripten (Debian: emscripten, node-acorn).
set -euo pipefail
src=$(cd "$(dirname "$0")" && pwd)
dir=${1:-$src/../build-wasm}
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
if [ ! -f "$dir/CMakeCache.txt" ]; then
  emcmake cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -G Ninja
fi
cmake --build "$dir"
