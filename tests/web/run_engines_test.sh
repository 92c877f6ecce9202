#!/usr/bin/env bash
# ctest driver of the engine drop tests:
#   run_engines_test.sh REPO BUILD_DIR HULLPACK WEB_BULLET_DROP WORK_DIR TEST_O3DGC WEB_DECODE_REF
# Packs samples/torus.obj in both collider forms, the animated Kenney character and a generated
# blob with morph targets (make_morph_glb.mjs), gets Bullet's resting height and the C++ reader's
# hull points (web_bullet_drop) and the C++ decode of the KHR file (`hullpack unpack`), makes a
# file with hulls in the earlier stream form (make_glb.mjs) and its C++ hull points, then runs
# tests/web/engines_test.mjs. Exit 77 = skipped.
set -euo pipefail
[ $# -eq 7 ] || { echo "usage: run_engines_test.sh REPO BUILD_DIR HULLPACK WEB_BULLET_DROP WORK_DIR TEST_O3DGC WEB_DECODE_REF" >&2; exit 64; }
repo=$1 build=$2 hullpack=$3 bullet=$4 work=$5 encoder=$6 decode_ref=$7
skip() { echo "SKIP: $*"; exit 77; }

command -v node >/dev/null || skip "node not installed (./setup.sh installs nodejs)"
[ -x /usr/bin/chromium ] || skip "/usr/bin/chromium not installed (./setup.sh installs chromium)"
if command -v emcc >/dev/null; then
  bash "$repo/web/build_wasm.sh" "$build/web-wasm" >/dev/null
elif [ ! -f "$repo/samples/web/dist/hullpack_decoder_wasm.wasm" ]; then
  skip "emcc not installed and no prebuilt decoder in samples/web/dist (./setup.sh installs emscripten)"
fi
rm -rf "$work" && mkdir -p "$work"
"$hullpack" pack "$repo/samples/torus.obj" -o "$work/omi.glb" --quiet
"$hullpack" pack "$repo/samples/torus.obj" -o "$work/khr.glb" --physics khr --quiet
"$hullpack" unpack "$work/khr.glb" -o "$work/khr.ref.glb" >/dev/null
"$hullpack" unpack "$work/omi.glb" -o "$work/omi.ref.glb" >/dev/null
# The animated character, with a stand-in for its palette texture (not part of the sample).
mkdir -p "$work/character/Textures"
cp "$repo/samples/assets/kenney_character.glb" "$work/character/"
base64 -d >"$work/character/Textures/colormap.png" <<<'iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg=='
"$hullpack" pack "$work/character/kenney_character.glb" -o "$work/character.glb" --quiet
node "$repo/tests/web/make_morph_glb.mjs" --out "$work/morph.source.glb"
"$hullpack" pack "$work/morph.source.glb" -o "$work/morph.glb" --quiet
"$bullet" "$work/omi.glb" >"$work/omi.bullet.json"
"$bullet" "$work/khr.glb" >"$work/khr.bullet.json"
node "$repo/tests/web/make_glb.mjs" --encoder "$encoder" --ref "$decode_ref" --mesh "$repo/samples/torus.obj" \
  --out "$work/earlier.glb" >/dev/null
"$bullet" "$work/earlier.glb" >"$work/earlier.bullet.json"
exec node "$repo/tests/web/engines_test.mjs" --repo "$repo" --work "$work"
