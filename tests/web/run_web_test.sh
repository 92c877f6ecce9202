#!/usr/bin/env bash
# ctest driver of the browser test:
#   run_web_test.sh REPO BUILD_DIR TEST_O3DGC WEB_DECODE_REF WORK_DIR [HULLPACK]
# Builds the wasm decoder (when emcc is there), makes the packed GLB from samples/torus.obj with the
# C++ encoder of this build (and with `hullpack pack`, both collider forms, when built), then runs
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
if [ -n "$hullpack" ] && "$hullpack" pack --help >/dev/null 2>&1; then
  "$hullpack" pack "$repo/samples/torus.obj" -o "$work/packed.glb" --quiet
  "$hullpack" pack "$repo/samples/torus.obj" -o "$work/packed_khr.glb" --physics khr --quiet
fi
exec node "$repo/tests/web/browser_test.mjs" --repo "$repo" --work "$work"
