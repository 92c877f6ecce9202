#!/usr/bin/env bash
# End-to-end checks of test_o3dgc and o3dgc_legacy_check: compress and decompress round trips keep
# the mesh, the original tool's spellings and the long ones give the same stream, streams of the
# original Open3DGC tool decode to its triangles, and mistakes exit 64 (usage) or 1 (input).
# usage: test_o3dgc_cli_test.sh TEST_O3DGC_BINARY O3DGC_LEGACY_CHECK_BINARY SOURCE_DIR
bin=$1
check=$2
src=$3
. "$src/tests/tools/cli_check.sh"

check_conventions test_o3dgc "$bin"
check_conventions o3dgc_legacy_check "$check"
run no-mode 64 "give one of -c and -d" -- "$bin" -i "$src/samples/torus.obj"
run both-modes 64 "give one of -c and -d" -- "$bin" -c -d -i "$src/samples/torus.obj"
run no-input 64 "missing -i INPUT" -- "$bin" -c
run bad-bits 64 "-qc takes a whole number in \[1, 30\]" -- "$bin" -c -i x.obj -qc 40
run bad-stream-type 64 "-st takes binary or ascii" -- "$bin" -c -i x.obj -st text

# Round trip of the sample: same vertex and triangle counts.
cp "$src/samples/torus.obj" "$tmp/torus.obj"
run compress 0 "Stream $tmp/torus.s3d (binary)" -- "$bin" -c -i "$tmp/torus.obj" -qc 12
run decompress 0 "Wrote $tmp/torus_dec.obj" -- "$bin" -d -i "$tmp/torus.s3d"
for tag in v f; do
  a=$(grep -c "^$tag " "$tmp/torus.obj")
  b=$(grep -c "^$tag " "$tmp/torus_dec.obj" 2>/dev/null)
  [ "$a" = "$b" ] && pass || fail "round trip: $a '$tag' lines in, ${b:-none} out"
done
# The long spellings give the same stream, the operand form too.
mv "$tmp/torus.s3d" "$tmp/short.s3d"
run long-options 0 "" -- "$bin" --compress --input "$tmp/torus.obj" --qp 12
cmp -s "$tmp/short.s3d" "$tmp/torus.s3d" && pass || fail "--qp 12 and -qc 12 give different streams"
run operand 0 "" -- "$bin" -c "$tmp/torus.obj" --qp=12
cmp -s "$tmp/short.s3d" "$tmp/torus.s3d" && pass || fail "the operand form gives another stream"
# ASCII streams are 7-bit; -keep keeps the order (the decoded OBJ's faces are the input's).
run ascii 0 "(ascii)" -- "$bin" -c -i "$tmp/torus.obj" -st ascii
high=$(od -An -v -tu1 "$tmp/torus.s3d" | tr -s ' ' '\n' | awk '$1 > 127' | wc -l)
[ "$high" -eq 0 ] && pass || fail "ASCII stream holds $high bytes above 127"
od -An -v -tu1 "$tmp/short.s3d" | tr -s ' ' '\n' | awk '$1 > 127' | grep -q . && pass ||
  fail "the binary stream looked 7-bit too: the check above could not fail"
run keep 0 "" -- "$bin" -c -i "$tmp/torus.obj" -keep -fast
run keep-decode 0 "" -- "$bin" -d -i "$tmp/torus.s3d"
diff <(grep '^f ' "$tmp/torus.obj" | tr -s ' ' | sed 's#/[0-9/]*##g') \
  <(grep '^f ' "$tmp/torus_dec.obj" | tr -s ' ' | sed 's#/[0-9/]*##g') >/dev/null && pass ||
  fail "-keep: decoded triangles differ from the input's"

# A generated cube with two materials: the group ids and names come back.
{
  printf 'mtllib none.mtl\n'
  printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n'
  printf 'usemtl red\nf 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n'
  printf 'usemtl blue\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n'
} >"$tmp/cube.obj"
run cube 0 "triangles 12" -- "$bin" -c -i "$tmp/cube.obj"
run cube-decode 0 "triangles 12" -- "$bin" -d -i "$tmp/cube.s3d"
grep -q '^usemtl red' "$tmp/cube_dec.obj" && grep -q '^usemtl blue' "$tmp/cube_dec.obj" && pass ||
  fail "materials lost: $(grep usemtl "$tmp/cube_dec.obj" | tr '\n' ' ')"

# Triangles with two corners at one position (a repeated index, a copied vertex) are left out
# unless --keep-degenerate is given.
{
  printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nv 0 0 0\n'
  printf 'f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n'
  printf 'f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\nf 1 1 2\nf 9 2 1\n'
} >"$tmp/slivers.obj"
run degenerate-left-out 0 "triangles 14" -- "$bin" -c -i "$tmp/slivers.obj"
run degenerate-left-out-decode 0 "triangles 12" -- "$bin" -d -i "$tmp/slivers.s3d"
grep -q "vertices 8$" "$tmp/out" && pass || fail "the copied vertex only a degenerate triangle used stayed"
run degenerate-kept 0 "triangles 14" -- "$bin" -c -i "$tmp/slivers.obj" --keep-degenerate
run degenerate-kept-decode 0 "triangles 14" -- "$bin" -d -i "$tmp/slivers.s3d"
grep -q "vertices 9$" "$tmp/out" && pass || fail "--keep-degenerate: a vertex went missing"

# Streams of the original Open3DGC tool: test_o3dgc decodes them to the original's triangles, and
# o3dgc_legacy_check agrees with the original decoder's OBJs (and notices one that differs).
mkdir "$tmp/legacy"
for name in cup.binary cup.binary_default fox.binary test_nm.binary vertex_color_test.binary; do
  cp "$src/tests/o3dgc/vectors/$name.s3d" "$src/tests/o3dgc/vectors/${name}_dec.obj" "$tmp/legacy/"
done
run legacy-decode 0 "Original Open3DGC stream (binary)" -- "$bin" -d -i "$tmp/legacy/fox.binary.s3d"
mv "$tmp/legacy/fox.binary_dec.obj" "$tmp/fox_ours.obj"
cp "$src/tests/o3dgc/vectors/fox.binary_dec.obj" "$tmp/legacy/"
diff <(grep '^f ' "$tmp/fox_ours.obj") <(grep '^f ' "$tmp/legacy/fox.binary_dec.obj") >/dev/null &&
  pass || fail "legacy decode: triangles differ from the original decoder's"
run legacy-check 0 "5 streams, 0 failed" -- "$check" "$tmp/legacy"
cp "$src/tests/o3dgc/vectors/cup.binary_dec.obj" "$tmp/legacy/fox.binary_dec.obj"
run legacy-check-mismatch 1 "5 streams, 1 failed" -- "$check" "$tmp/legacy"

# Bad input: exit 1 and the file named.
run missing-file 1 "$tmp/none.obj" -- "$bin" -c -i "$tmp/none.obj"
head -c 100 "$tmp/short.s3d" >"$tmp/truncated.s3d"
run truncated-stream 1 "decode failed" -- "$bin" -d -i "$tmp/truncated.s3d"
[ -e "$tmp/truncated_dec.obj" ] && fail "a failed decode left an output" || pass

finish
