#!/usr/bin/env bash
# End-to-end checks of testHACD: the original positional form and named options decompose, a
# convex input gives one hull, two boxes joined by a bar three, the options reach the library, and
# mistakes exit 64 with one line.
# usage: testhacd_cli_test.sh TESTHACD_BINARY SOURCE_DIR
bin=$1
src=$2
. "$src/tests/tools/cli_check.sh"

box_obj() {  # box_obj X0 Y0 Z0 X1 Y1 Z1 FIRST_VERTEX_INDEX
  local x0=$1 y0=$2 z0=$3 x1=$4 y1=$5 z1=$6 b=$7
  printf 'v %s %s %s\nv %s %s %s\nv %s %s %s\nv %s %s %s\n' $x0 $y0 $z0 $x1 $y0 $z0 $x1 $y1 $z0 \
    $x0 $y1 $z0
  printf 'v %s %s %s\nv %s %s %s\nv %s %s %s\nv %s %s %s\n' $x0 $y0 $z1 $x1 $y0 $z1 $x1 $y1 $z1 \
    $x0 $y1 $z1
  local f
  for f in "1 3 2" "1 4 3" "5 6 7" "5 7 8" "1 2 6" "1 6 5" "2 3 7" "2 7 6" "3 4 8" "3 8 7" \
    "4 1 5" "4 5 8"; do
    set -- $f
    printf 'f %d %d %d\n' $(($1 + b)) $(($2 + b)) $(($3 + b))
  done
}
box_obj 0 0 0 1 1 1 0 >"$tmp/cube.obj"
samples_torus="$src/samples/torus.obj"
{ box_obj 0 0 0 2 2 2 0; box_obj 4 0 0 6 2 2 8; box_obj 2 0.9 0.9 4 1.1 1.1 16; } >"$tmp/dumbbell.obj"

check_conventions testHACD "$bin"
run no-args 64 "missing INPUT" -- "$bin"

# The original positional form, with named options after it.
run positional 0 "hulls: 1 " -- "$bin" "$tmp/cube.obj" 1 100 0 1 1 30 2000 -o "$tmp/cube.wrl"
grep -q "IndexedFaceSet" "$tmp/cube.wrl" 2>/dev/null && pass || fail "positional: no hull in the VRML"
run positional-bad-flag 64 "--invert-faces takes 0 or 1" -- "$bin" "$tmp/cube.obj" 2 100 2 1 1 30 2000

# Named options: the dumbbell gives three hulls, --report and --log tell.
run named 0 "wrote $tmp/d.json" -- "$bin" "$tmp/dumbbell.obj" --preset recommended \
  -o "$tmp/d_hulls.obj" --report "$tmp/d.json" --log "$tmp/d.log" --threads 1
hulls=$(grep -c '^o ' "$tmp/d_hulls.obj" 2>/dev/null)
[ "${hulls:-0}" -eq 3 ] && pass || fail "named: the dumbbell gave ${hulls:-no} hulls, expected 3"
grep -q '"method": "hacd"' "$tmp/d.json" && grep -q '"hull_count": 3,' "$tmp/d.json" && pass ||
  fail "named: report: $(head -c 200 "$tmp/d.json")"
[ -s "$tmp/d.log" ] && pass || fail "named: empty log"
run min-clusters 0 "hulls: 3 " -- "$bin" "$tmp/cube.obj" --min-clusters 3 --no-report
# The targets: an exact count, a budget, a target error.
run hull-count 0 "hulls: 5 " -- "$bin" "$samples_torus" --preset recommended --hulls 5 --no-report
run hull-count-short 0 "target not reached: the surface could be clustered into only 12" -- \
  "$bin" "$tmp/cube.obj" --hulls 20 --no-report
run max-hulls 0 "hulls: 2 " -- "$bin" "$samples_torus" --preset recommended --max-hulls 2 --no-report
run max-concavity 0 "hulls: " -- "$bin" "$samples_torus" --preset recommended --max-concavity 0.05 \
  --report "$tmp/t.json"
grep -q '"attempts": [1-3],' "$tmp/t.json" && pass || fail "max-concavity: no attempts in the report"
run sample 0 "561 points, 1024 triangles" -- "$bin" "$src/samples/torus.obj" -o "$tmp/torus.glb"
[ -s "$tmp/torus.glb" ] && pass || fail "sample: no GLB written"

# Mistakes: usage errors exit 64 with one line; a bad input exits 1 naming the file.
run bad-preset 64 "--preset takes default or recommended" -- "$bin" "$tmp/cube.obj" --preset x
run out-of-range 64 "--max-vertices" -- "$bin" "$tmp/cube.obj" --max-vertices 2
run bad-target 64 "--max-concavity" -- "$bin" "$tmp/cube.obj" --max-concavity 2
run two-inputs 64 "unexpected argument" -- "$bin" "$tmp/cube.obj" "$tmp/cube.obj"
run missing-file 1 "$tmp/none.obj" -- "$bin" "$tmp/none.obj"

finish
