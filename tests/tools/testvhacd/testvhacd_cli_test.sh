#!/usr/bin/env bash
# End-to-end checks of testVHACD: both command-line forms decompose, a convex input gives one hull,
# a concave one several, the options reach the library, and mistakes exit 64 with one line.
# usage: testvhacd_cli_test.sh TESTVHACD_BINARY SOURCE_DIR
bin=$1
src=$2
. "$src/tests/tools/cli_check.sh"

# A unit cube (convex) and an L-shaped prism (concave: two boxes side by side), as OBJ.
box_obj() {  # box_obj X0 Y0 X1 Y1 FIRST_VERTEX_INDEX
  local x0=$1 y0=$2 x1=$3 y1=$4 b=$5
  printf 'v %s %s 0\nv %s %s 0\nv %s %s 0\nv %s %s 0\n' $x0 $y0 $x1 $y0 $x1 $y1 $x0 $y1
  printf 'v %s %s 1\nv %s %s 1\nv %s %s 1\nv %s %s 1\n' $x0 $y0 $x1 $y0 $x1 $y1 $x0 $y1
  local f
  for f in "1 3 2" "1 4 3" "5 6 7" "5 7 8" "1 2 6" "1 6 5" "2 3 7" "2 7 6" "3 4 8" "3 8 7" \
    "4 1 5" "4 5 8"; do
    set -- $f
    printf 'f %d %d %d\n' $(($1 + b)) $(($2 + b)) $(($3 + b))
  done
}
box_obj 0 0 1 1 0 >"$tmp/cube.obj"
# The L: a 4x1 bar along x and a 1x3 bar along y at its end, as one closed surface would need a
# shared wall; two touching closed boxes are enough for the decomposition to see a concave solid.
{ box_obj 0 0 4 1 0; box_obj 0 1 1 4 8; } >"$tmp/l.obj"

check_conventions testVHACD "$bin"
run no-args 64 "missing INPUT" -- "$bin"

# V-HACD 2.0's positional form.
run positional 0 "hulls: 1 " -- "$bin" "$tmp/cube.obj" 10000 20 0.0025 4 4 0.05 0.05 0.00125 0 0 \
  64 0.0 "$tmp/cube.wrl" "$tmp/cube.log"
grep -q "IndexedFaceSet" "$tmp/cube.wrl" 2>/dev/null && pass || fail "positional: no hull in the VRML"
[ -s "$tmp/cube.log" ] && pass || fail "positional: empty log"
run positional-bad-mode 64 "mode must be 0 or 1" -- "$bin" "$tmp/cube.obj" 10000 20 0.0025 4 4 0.05 \
  0.05 0.00125 0 2 64 0.0 "$tmp/x.wrl" "$tmp/x.log"

# Named options: a concave input gives several hulls, --max-hulls caps them, --report tells.
run named 0 "wrote $tmp/l.json" -- "$bin" "$tmp/l.obj" -o "$tmp/l_hulls.obj" --report "$tmp/l.json" \
  --resolution 20000
hulls=$(grep -c '^o ' "$tmp/l_hulls.obj" 2>/dev/null)
[ "${hulls:-0}" -ge 2 ] && pass || fail "named: the L-shape gave ${hulls:-no} hulls, expected >= 2"
grep -q "\"hull_count\": $hulls," "$tmp/l.json" && pass || fail "named: report disagrees: $(head -c 200 "$tmp/l.json")"
run max-hulls 0 "hulls: 1 " -- "$bin" "$tmp/l.obj" -o "$tmp/l_one.obj" --resolution 20000 \
  --max-hulls 1 --quality high
run tetra 0 "hulls:" -- "$bin" "$tmp/cube.obj" --mode tetra --resolution 10000 --threads 1
run sample 0 "561 points, 1024 triangles" -- "$bin" "$src/samples/torus.obj" --resolution 10000 \
  -o "$tmp/torus_hulls.glb"
[ -s "$tmp/torus_hulls.glb" ] && pass || fail "sample: no GLB written"
# --points-in-place reaches the library and gives the same hulls: an L prism as one closed
# surface (every point used once, none repeated: read in place).
{
  printf 'v %s %s 0\n' 0 0 4 0 4 1 1 1 1 4 0 4
  printf 'v %s %s 1\n' 0 0 4 0 4 1 1 1 1 4 0 4
  printf 'f %s\n' "1 4 2" "2 4 3" "1 5 4" "1 6 5" "7 8 10" "8 9 10" "7 10 11" "7 11 12"
  for i in 1 2 3 4 5 6; do
    j=$((i % 6 + 1))
    printf 'f %d %d %d\nf %d %d %d\n' $i $j $((j + 6)) $i $((j + 6)) $((i + 6))
  done
} >"$tmp/l_prism.obj"
run in-place-copy 0 "hulls:" -- "$bin" "$tmp/l_prism.obj" -o "$tmp/l_copy.obj" --resolution 20000
run in-place 0 "hulls:" -- "$bin" "$tmp/l_prism.obj" -o "$tmp/l_in_place.obj" \
  --resolution 20000 --points-in-place
hulls=$(grep -c '^o ' "$tmp/l_in_place.obj" 2>/dev/null)
[ "${hulls:-0}" -ge 2 ] && pass || fail "in-place: the L prism gave ${hulls:-no} hulls, expected >= 2"
cmp -s "$tmp/l_copy.obj" "$tmp/l_in_place.obj" && pass || fail "in-place: other hulls than the copy"

# Mistakes: usage errors exit 64 with one line; a bad input exits 1 naming the file.
run bad-mode 64 "--mode takes voxel, tetra" -- "$bin" "$tmp/cube.obj" --mode foo
run missing-value 64 "--resolution needs a value" -- "$bin" "$tmp/cube.obj" --resolution
run out-of-range 64 "resolution" -- "$bin" "$tmp/cube.obj" --resolution 5
run two-inputs 64 "unexpected argument" -- "$bin" "$tmp/cube.obj" "$tmp/l.obj"
run missing-file 1 "$tmp/none.obj" -- "$bin" "$tmp/none.obj"
printf 'v 0 0 0\nf 1 2 3\n' >"$tmp/broken.obj"
run broken-file 1 "$tmp/broken.obj" -- "$bin" "$tmp/broken.obj"

finish
