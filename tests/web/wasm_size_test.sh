#!/usr/bin/env bash
# ctest driver of the WebAssembly decoder's download size:
#   wasm_size_test.sh REPO BUILD_DIR LIMIT_BYTES
# Builds the decoder (when emcc is there; web_browser builds the same tree) and checks that its
# .wasm plus its .js glue, each compressed with gzip -9 as a server would send them, stay within
# LIMIT_BYTES. Exit 77 = skipped (no emcc and no prebuilt decoder).
set -euo pipefail
repo=$1 build=$2 limit=$3
dist="$repo/samples/web/dist"
if command -v emcc >/dev/null; then
  bash "$repo/web/build_wasm.sh" "$build/web-wasm" >/dev/null
elif [ ! -f "$dist/hullpack_decoder_wasm.wasm" ]; then
  echo "SKIP: emcc not installed and no prebuilt decoder in samples/web/dist (./setup.sh installs emscripten)"
  exit 77
fi
total=0
for f in "$dist/hullpack_decoder_wasm.wasm" "$dist/hullpack_decoder_wasm.js"; do
  n=$(gzip -9c "$f" | wc -c)
  echo "$(basename "$f"): $(stat -c %s "$f") bytes, $n gzip'd"
  total=$((total + n))
done
echo "gzip'd decoder: $total bytes (limit $limit)"
if [ "$total" -gt "$limit" ]; then
  echo "FAIL: the gzip'd WebAssembly decoder grew past $limit bytes"
  exit 1
fi
