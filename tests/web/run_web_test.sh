#!/usr/bin/env bash
# ctest driver of the browser test:
#   run_web_test.sh REPO BUILD_DIR TEST_O3DGC WEB_DECODE_REF WORK_DIR [HULLPACK]
# Builds the wasm decoder (when emcc is there), makes the packed GLB from samples/torus.obj with the
# C++ encoder of this build, packs samples/torus.obj (both collider forms) and a generated skinned
# mesh with `hullpack pack` and decodes each with `hullpack unpack` (the C++ reference), then runs
# tests/web/browser_test.mjs. Exit 77 = skipped.
set -euo pipefail
repo=$1 build=$2 encoder=$3 ref=$4 work=$5 hullpack=${6:-}
skip() { echo "SKIP: $*"; exit 77; }

command -v node >/dev/null || skip "node not installed (./setup.sh installs nodejs)"
[ -x /usr/bin/chromium ] || skip "/usr/bin/chromium not installed (./setup.sh installs chromium)"
[ -d "$repo/node_modules/playwright-core" ] && [ -d "$repo/node_modules/three" ] ||
  skip "npm packages playwright-core/three missing (npm ci at the repository root)"
if command -v emcc >/dev/null; then
  bash "$repo/web/build_wasm.sh" "$build/web-wasm" >/dev/null
elif [ ! -f "$repo/samples/web/dist/hullpack_decoder_wasm.wasm" ]; then
  skip "emcc not installed and no prebuilt decoder in samples/web/dist (./setup.sh installs emscripten)"
fi

rm -rf "$work" && mkdir -p "$work"
node "$repo/tests/web/make_glb.mjs" --encoder "$encoder" --ref "$ref" --mesh "$repo/samples/torus.obj" --out "$work/torus.glb"
if [ -n "$hullpack" ]; then
  [ -x "$hullpack" ] || { echo "FAIL: $hullpack is not built (cmake --build BUILD --target hullpack)"; exit 1; }
  "$hullpack" pack "$repo/samples/torus.obj" -o "$work/packed.glb" --quiet
  "$hullpack" pack "$repo/samples/torus.obj" -o "$work/packed_khr.glb" --physics khr --quiet
  "$hullpack" pack "$repo/samples/torus.obj" -o "$work/packed_fast.glb" --fast-decode --quiet
  # A skinned mesh generated in code (float weights whose quantized sums are not 1).
  node "$repo/tests/web/make_skinned_glb.mjs" --out "$work/skinned.glb"
  "$hullpack" pack "$work/skinned.glb" -o "$work/skinned.packed.glb" --quiet
  # The C++ reader's answer for every packed file: the same document, every compressed primitive
  # decoded into plain accessors (skin weights renormalized as docs/packed-gltf.md says).
  for f in packed packed_khr packed_fast skinned.packed; do
    "$hullpack" unpack "$work/$f.glb" -o "$work/$f.ref.glb" >/dev/null
  done
fi
exec node "$repo/tests/web/browser_test.mjs" --repo "$repo" --work "$work"
