#!/usr/bin/env bash
# End-to-end checks of `hullpack pack` and `hullpack unpack`: outputs that validate, reports, batch
# mode, exit status = failures, no overwriting without --force, never an input.
# usage: pack_cli_test.sh HULLPACK_BINARY SOURCE_DIR [NODE]
set -u
bin=$1
src=$2
node=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }

run() {  # run EXPECTED_EXIT NAME -- command...
  local want=$1 name=$2
  shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  if [ "$rc" -ge 128 ]; then fail "$name: crashed ($rc)"; return 1; fi
  if [ "$rc" -ne "$want" ]; then fail "$name: exit $rc, expected $want: $(head -c 400 "$tmp/err")"; return 1; fi
  pass
}

sample=$src/samples/torus.obj
run 0 pack -- "$bin" pack "$sample" -o "$tmp/t.glb" --report "$tmp/t.json" --quiet
[ -s "$tmp/t.glb" ] && pass || fail "pack wrote nothing"
grep -q '"hull_count"' "$tmp/t.json" && grep -q '"max_error_fraction"' "$tmp/t.json" && pass || fail "report lacks fields"
# The write stage (temp file + rename) is timed: a positive number, not the 0 of an untimed stage.
grep -Eq '"write": [0-9.]+e-[0-9]+|"write": 0\.[0-9]*[1-9]' "$tmp/t.json" && pass || fail "seconds.write is not timed: $(grep '"write"' "$tmp/t.json")"
run 0 info-packed -- "$bin" info "$tmp/t.glb"
cp "$tmp/t.glb" "$tmp/hulls.glb"  # compressed mesh + OMI hulls, no fallback (validated below)
grep -q '"hull_position_bits"' "$tmp/t.json" && grep -q '"hull_encode"' "$tmp/t.json" && pass || fail "report lacks hull fields"
run 1 refuse-existing -- "$bin" pack "$sample" -o "$tmp/t.glb" --quiet
grep -q "exists (use --force" "$tmp/err" && pass || fail "refusal message: $(cat "$tmp/err")"
run 0 force -- "$bin" pack "$sample" -o "$tmp/t.glb" --force --quiet --hulls none
cp "$sample" "$tmp/in.obj"
cp "$tmp/t.glb" "$tmp/in.glb"
run 1 never-the-input -- "$bin" pack "$tmp/in.glb" -o "$tmp/in.glb" --force --quiet
cmp -s "$tmp/t.glb" "$tmp/in.glb" && pass || fail "the input was changed"
run 0 unpack-glb -- "$bin" unpack "$tmp/t.glb" -o "$tmp/plain.glb"
run 0 unpack-obj -- "$bin" unpack "$tmp/t.glb" -o "$tmp/plain.obj"
run 0 info-unpacked -- "$bin" info "$tmp/plain.obj"
grep -q "triangles 1024" "$tmp/out" && pass || fail "unpacked OBJ: $(cat "$tmp/out")"
# With hulls: OBJ and WRL get each hull as a closed mesh after the render mesh; OFF and PLY (one
# mesh per file) get them in STEM.hulls.off / .ply.
hulls=$(grep -o '"hull_count": *[0-9]*' "$tmp/t.json" | grep -o '[0-9]*$')
run 0 unpack-hulls-obj -- "$bin" unpack "$tmp/hulls.glb" -o "$tmp/h.obj"
[ "$(grep -c '^o hull_' "$tmp/h.obj")" = "$hulls" ] && pass || fail "OBJ hull objects: $(grep -c '^o hull_' "$tmp/h.obj"), report $hulls"
grep -q "$hulls hulls" "$tmp/out" && pass || fail "unpack summary: $(cat "$tmp/out")"
run 0 info-hulls-obj -- "$bin" info "$tmp/h.obj"
grep -q "meshes $((hulls + 1))" "$tmp/out" && pass || fail "OBJ read back: $(cat "$tmp/out")"
# .gltf: the same document as JSON, its buffer beside it under a URI (escaped: a space in the name).
run 0 unpack-hulls-gltf -- "$bin" unpack "$tmp/hulls.glb" -o "$tmp/h plain.gltf"
[ -s "$tmp/h plain.bin" ] && pass || fail ".gltf buffer not written: $(cat "$tmp/out")"
grep -q '"uri":"h%20plain.bin"' "$tmp/h plain.gltf" && pass || fail ".gltf buffer uri: $(grep -o '"buffers":[^]]*' "$tmp/h plain.gltf")"
run 0 info-hulls-gltf -- "$bin" info "$tmp/h plain.gltf"
grep -q "triangles 1024" "$tmp/out" && grep -q "collision hulls $hulls " "$tmp/out" && pass ||
  fail ".gltf read back: $(cat "$tmp/out")"
cp "$tmp/h plain.gltf" "$tmp/hv.gltf"
cp "$tmp/h plain.bin" "$tmp/hv.bin"
sed -i 's/h%20plain.bin/hv.bin/' "$tmp/hv.gltf"
rm "$tmp/h plain.gltf"
run 1 unpack-gltf-buffer-exists -- "$bin" unpack "$tmp/hulls.glb" -o "$tmp/h plain.gltf"
[ ! -e "$tmp/h plain.gltf" ] && pass || fail ".gltf written although its buffer's file exists"
run 0 unpack-hulls-wrl -- "$bin" unpack "$tmp/hulls.glb" -o "$tmp/h.wrl"
run 0 info-hulls-wrl -- "$bin" info "$tmp/h.wrl"
grep -q "meshes $((hulls + 1))" "$tmp/out" && pass || fail "WRL read back: $(cat "$tmp/out")"
for ext in off ply; do
  run 0 unpack-hulls-$ext -- "$bin" unpack "$tmp/hulls.glb" -o "$tmp/h.$ext"
  run 0 info-render-$ext -- "$bin" info "$tmp/h.$ext"
  grep -q "triangles 1024" "$tmp/out" && pass || fail "$ext render mesh: $(cat "$tmp/out")"
  run 0 info-hulls-$ext -- "$bin" info "$tmp/h.hulls.$ext"
  grep -q "triangles [1-9]" "$tmp/out" && pass || fail "$ext hulls: $(cat "$tmp/out")"
  # The hulls' file is not replaced without --force either (and then nothing is written).
  rm "$tmp/h.$ext"
  run 1 unpack-hulls-$ext-exists -- "$bin" unpack "$tmp/hulls.glb" -o "$tmp/h.$ext"
  [ ! -e "$tmp/h.$ext" ] && pass || fail "$ext written although its hulls' file exists"
done

# --fast-decode: another stream (values in vertex id order), the same decoded mesh on the same
# grid (with --max-error each order may find another grid smallest).
run 0 pack-default -- "$bin" pack "$sample" -o "$tmp/order_default.glb" --hulls none --qp 14 --quiet
run 0 pack-fast -- "$bin" pack "$sample" -o "$tmp/order_fast.glb" --hulls none --qp 14 --fast-decode --quiet
cmp -s "$tmp/order_default.glb" "$tmp/order_fast.glb" && fail "--fast-decode wrote the default stream" || pass
run 0 unpack-default -- "$bin" unpack "$tmp/order_default.glb" -o "$tmp/order_default.obj"
run 0 unpack-fast -- "$bin" unpack "$tmp/order_fast.glb" -o "$tmp/order_fast.obj"
cmp -s "$tmp/order_default.obj" "$tmp/order_fast.obj" && pass || fail "--fast-decode decodes to another mesh"
# --max-compression: a smaller stream (format 1.3) of a mesh past 4096 vertices, the same mesh
# decoded; not with --fast-decode.
scan=$src/samples/scans/thorvaldsen_maria.glb
run 0 pack-scan-default -- "$bin" pack "$scan" -o "$tmp/scan_default.glb" --hulls none --qp 14 --quiet
run 0 pack-scan-max -- "$bin" pack "$scan" -o "$tmp/scan_max.glb" --hulls none --qp 14 --max-compression --quiet
[ "$(stat -c %s "$tmp/scan_max.glb")" -lt "$(stat -c %s "$tmp/scan_default.glb")" ] && pass ||
  fail "--max-compression: $(stat -c %s "$tmp/scan_max.glb") bytes, default $(stat -c %s "$tmp/scan_default.glb")"
run 0 unpack-scan-default -- "$bin" unpack "$tmp/scan_default.glb" -o "$tmp/scan_default.obj"
run 0 unpack-scan-max -- "$bin" unpack "$tmp/scan_max.glb" -o "$tmp/scan_max.obj"
cmp -s "$tmp/scan_default.obj" "$tmp/scan_max.obj" && pass || fail "--max-compression decodes to another mesh"
run 64 max-and-fast -- "$bin" pack "$scan" -o "$tmp/scan_both.glb" --max-compression --fast-decode --quiet
grep -q "exclude each other" "$tmp/err" && pass || fail "--max-compression --fast-decode: $(cat "$tmp/err")"

# Batch into a folder: one bad input among good ones.
mkdir "$tmp/batch"
printf 'not a mesh\n' >"$tmp/bad.obj"
cp "$sample" "$tmp/second.obj"
run 1 batch-one-failure -- "$bin" pack "$tmp/in.obj" "$tmp/bad.obj" "$tmp/second.obj" -o "$tmp/batch/" --quiet --hulls none
[ -s "$tmp/batch/in.packed.glb" ] && [ -s "$tmp/batch/second.packed.glb" ] && [ ! -e "$tmp/batch/bad.packed.glb" ] && pass ||
  fail "batch outputs: $(ls "$tmp/batch")"
grep -q "$tmp/bad.obj" "$tmp/err" && pass || fail "batch error does not name the file"
ls "$tmp/batch" | grep -q tmp && fail "temporary file left behind" || pass
run 64 usage -- "$bin" pack "$sample"
# --hulls N: exactly N hulls for the torus; --max-concavity D; a bad count is a usage error.
run 0 hulls-count -- "$bin" pack "$sample" -o "$tmp/n.glb" --hulls 5 --report "$tmp/n.json" --quiet
grep -q '"hull_count": *5[,}]' "$tmp/n.json" && pass || fail "--hulls 5: $(grep -o '"hull_count": *[0-9]*' "$tmp/n.json")"
run 0 max-concavity -- "$bin" pack "$sample" -o "$tmp/d.glb" --max-concavity 0.05 --report "$tmp/d.json" --quiet
grep -q '"target_reached": *true' "$tmp/d.json" && pass || fail "--max-concavity 0.05 not reported as reached"
# A target finer than the voxel grid can give: the report says so, and why. (Slices only: the
# second, oriented decomposition would only make the miss take twice as long.)
run 0 max-concavity-missed -- "$bin" pack "$sample" -o "$tmp/d2.glb" --max-concavity 0.01 --no-oriented-cuts \
  --report "$tmp/d2.json" --quiet
grep -q '"target_reached": *false' "$tmp/d2.json" && grep -q '"target_note": *"max_concavity' "$tmp/d2.json" &&
  pass || fail "--max-concavity 0.01: target_reached/target_note missing from the report"
run 64 bad-hull-count -- "$bin" pack "$sample" -o "$tmp/x.glb" --hulls 0
# --method hacd takes the count, the budget and the target; the voxel options are usage errors.
run 0 hacd-count -- "$bin" pack "$sample" -o "$tmp/h.glb" --method hacd --hulls 4 --report "$tmp/h.json" --quiet
grep -q '"hull_count": *4[,}]' "$tmp/h.json" && pass || fail "hacd --hulls 4: $(grep -o '"hull_count": *[0-9]*' "$tmp/h.json")"
run 0 hacd-budget -- "$bin" pack "$sample" -o "$tmp/hb.glb" --method hacd --max-hulls 2 --report "$tmp/hb.json" --quiet
grep -q '"hull_count": *2[,}]' "$tmp/hb.json" && pass || fail "hacd --max-hulls 2: $(grep -o '"hull_count": *[0-9]*' "$tmp/hb.json")"
run 0 hacd-target -- "$bin" pack "$sample" -o "$tmp/ht.glb" --method hacd --max-concavity 0.05 --concavity 0.04 --quiet
run 64 hacd-resolution -- "$bin" pack "$sample" -o "$tmp/x.glb" --method hacd --resolution 20000
run 64 hacd-quality -- "$bin" batch "$sample" -o "$tmp/xb" --method hacd --quality high
run 64 bad-option -- "$bin" pack "$sample" -o "$tmp/x.glb" --max-error -1

# Oriented cuts: an L prism turned 30 and 45 degrees about two axes splits along its own axes, so
# its two hulls are far closer than with cuts along the grid's axes alone (--no-oriented-cuts);
# by default both ways are tried and the closer kept.
cat >"$tmp/rot_l.obj" <<'OBJ'
v 0.000000 0.000000 0.000000
v 2.121320 2.121320 0.000000
v 1.508948 2.733693 0.500000
v 0.094734 1.319479 0.500000
v -1.130011 2.544224 1.500000
v -1.837117 1.837117 1.500000
v 0.353553 -0.353553 0.866025
v 2.474874 1.767767 0.866025
v 1.862501 2.380139 1.366025
v 0.448288 0.965926 1.366025
v -0.776457 2.190671 2.366025
v -1.483564 1.483564 2.366025
v 0.047367 0.659740 0.250000
v 0.400921 0.306186 1.116025
f 13 2 1
f 14 7 8
f 1 2 8
f 1 8 7
f 13 3 2
f 14 8 9
f 2 3 9
f 2 9 8
f 13 4 3
f 14 9 10
f 3 4 10
f 3 10 9
f 13 5 4
f 14 10 11
f 4 5 11
f 4 11 10
f 13 6 5
f 14 11 12
f 5 6 12
f 5 12 11
f 13 1 6
f 14 12 7
f 6 1 7
f 6 7 12
OBJ
concavity() { grep -o '"concavity": *[0-9.e-]*' "$1" | head -1 | grep -o '[0-9.e-]*$'; }
run 0 grid-cuts -- "$bin" pack "$tmp/rot_l.obj" -o "$tmp/rot_grid.glb" --hulls 2 --no-oriented-cuts \
  --resolution 30000 --report "$tmp/rot_grid.json" --quiet
run 0 auto-cuts -- "$bin" pack "$tmp/rot_l.obj" -o "$tmp/rot_auto.glb" --hulls 2 --resolution 30000 \
  --report "$tmp/rot_auto.json" --quiet
run 0 oriented-cuts -- "$bin" pack "$tmp/rot_l.obj" -o "$tmp/rot_oriented.glb" --hulls 2 --oriented-cuts \
  --resolution 30000 --report "$tmp/rot_oriented.json" --quiet
awk -v g="$(concavity "$tmp/rot_grid.json")" -v o="$(concavity "$tmp/rot_oriented.json")" \
  'BEGIN { exit !(o > 0 && o < g / 2) }' && pass ||
  fail "oriented cuts: concavity $(concavity "$tmp/rot_oriented.json") against $(concavity "$tmp/rot_grid.json") without"
awk -v g="$(concavity "$tmp/rot_grid.json")" -v a="$(concavity "$tmp/rot_auto.json")" \
  'BEGIN { exit !(a > 0 && a < g / 2) }' && pass ||
  fail "default cuts: concavity $(concavity "$tmp/rot_auto.json") against $(concavity "$tmp/rot_grid.json") without"

# The Khronos validator on the packed and unpacked files (skipped without node + gltf-validator).
if [ -n "$node" ] && [ -f "$src/node_modules/gltf-validator/package.json" ]; then
  run 0 pack-khr -- "$bin" pack "$sample" -o "$tmp/khr.glb" --physics khr --fallback --quiet
  for f in hulls.glb t.glb plain.glb hv.gltf khr.glb batch/in.packed.glb; do
    run 0 "validate-$f" -- "$node" "$src/tests/tools/gltf/validate_gltf.mjs" "$tmp/$f"
  done
else
  echo "validator checks skipped: node or the gltf-validator package is missing"
fi

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
