#!/usr/bin/env bash
# `hullpack pack` on the glTF writer's rich sample (skinned mesh, two UV sets, materials, an external
# texture beside the file): the packed file stands alone (the texture is embedded: the validator
# runs after the input folder is gone), and the packed file with --fallback and hulls on every mesh,
# and its unpacked plain GLB, pass the Khronos validator.
# usage: pack_rich_test.sh HULLPACK_BINARY SAMPLES_DIR SOURCE_DIR NODE
set -u
bin=$1
samples=$2
src=$3
node=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

mkdir "$tmp/in" "$tmp/out"
cp -r "$samples/rich.glb" "$samples/textures" "$tmp/in/"
"$bin" pack "$tmp/in/rich.glb" -o "$tmp/out/rich.glb" --fallback --hulls all --skinned-hulls --quiet >"$tmp/log" 2>&1 ||
  fail "pack: $(cat "$tmp/log")"
grep -q "embedded 1 external images" "$tmp/log" || fail "texture not embedded: $(cat "$tmp/log")"
"$bin" unpack "$tmp/out/rich.glb" -o "$tmp/out/plain.glb" >"$tmp/log" 2>&1 || fail "unpack: $(cat "$tmp/log")"
if [ -n "$node" ] && [ -f "$src/node_modules/gltf-validator/package.json" ]; then
  rm -r "$tmp/in"  # nothing may still point at the input's folder
  for f in rich.glb plain.glb; do
    "$node" "$src/tests/tools/gltf/validate_gltf.mjs" "$tmp/out/$f" >"$tmp/log" 2>&1 || fail "validate $f: $(cat "$tmp/log")"
  done
else
  echo "validator checks skipped: node or the gltf-validator package is missing"
fi
[ "$failures" -eq 0 ] && echo "pack_rich: ok"
[ "$failures" -eq 0 ]
