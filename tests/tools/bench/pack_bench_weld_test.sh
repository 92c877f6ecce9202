#!/bin/sh
# pack_bench on a cube whose two triangles per face carry normals that differ in their last bits
# (as CAD exporters write them): the encoder welds the corners whose normals it stores alike, and
# pack_bench must count the unpacked vertices as welded, not report lost data.
# Usage: pack_bench_weld_test.sh PACK_BENCH
set -eu
pack_bench=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/faceted_cube.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 -1
vn 0 0 -0.99999994
vn 0 0 1
vn 0 0 0.99999994
vn 0 -1 0
vn 0 -0.99999994 0
vn 0 1 0
vn 0 0.99999994 0
vn -1 0 0
vn -0.99999994 0 0
vn 1 0 0
vn 0.99999994 0 0
f 1//1 3//1 2//1
f 1//2 4//2 3//2
f 5//3 6//3 7//3
f 5//4 7//4 8//4
f 1//5 2//5 6//5
f 1//6 6//6 5//6
f 4//7 8//7 7//7
f 4//8 7//8 3//8
f 1//9 5//9 8//9
f 1//10 8//10 4//10
f 2//11 3//11 7//11
f 2//12 7//12 6//12
OBJ
"$pack_bench" "$dir" --max-error 0.0005 > "$dir/out.txt" 2>&1 || {
  cat "$dir/out.txt"
  exit 1
}
grep -q "faceted_cube" "$dir/out.txt"
