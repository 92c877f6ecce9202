#!/usr/bin/env bash
# End-to-end checks of `hullpack batch` and `hullpack pack --cache` on generated assets: summaries,
# one failing asset, a second run all from the cache, one changed input (or referenced file)
# recomputed alone, the same bytes for any --jobs, a SIGKILLed run resumed, shards merged.
# usage: batch_cli_test.sh HULLPACK_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
bg=
trap '[ -n "$bg" ] && kill -9 "$bg" 2>/dev/null; rm -rf "$tmp"' EXIT
failures=0
passes=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
check() { if eval "$2"; then passes=$((passes + 1)); else fail "$1"; fi; }
count() { grep -c "\"status\": \"$2\"" "$1"; }  # count SUMMARY STATUS
same_outputs() {  # same_outputs DIR_A DIR_B: every .packed.glb of A is in B with the same bytes
  local f n=0
  for f in $(cd "$1" && find . -name '*.packed.glb' | sort); do
    cmp -s "$1/$f" "$2/$f" || return 1
    n=$((n + 1))
  done
  [ "$n" -gt 0 ] && [ "$n" = "$(cd "$2" && find . -name '*.packed.glb' | wc -l)" ]
}

# A coarse, slices-only decomposition: this test is about the batch (cache, resume, signals), and
# under the sanitizers the default's second, oriented-cut decomposition doubles its time.
opts=(--resolution 10000 --max-hulls 4 --no-oriented-cuts --quiet)
"$src/tests/tools/batch/make_assets.sh" "$tmp/in" 10
mkdir -p "$tmp/in/sub"
mv "$tmp/in/asset009.obj" "$tmp/in/sub/"
printf 'v 0 0 0\nf 1 2 3\n' >"$tmp/in/broken.obj"
{
  echo "# the test batch"
  (cd "$tmp/in" && ls asset*.obj)
  echo "broken.obj"
  echo "sub/asset009.obj"
} >"$tmp/in/manifest.txt"

# First run: one failure, the others packed; summaries; exit status 1.
"$bin" batch --manifest "$tmp/in/manifest.txt" -o "$tmp/out" --jobs 2 "${opts[@]}" >"$tmp/o1" 2>"$tmp/e1"
check "first run exits 1 when an asset failed (got $?)" '[ $? = 1 ]'
check "summary.json and .csv" '[ -s "$tmp/out/summary.json" ] && [ -s "$tmp/out/summary.csv" ]'
check "10 packed, 1 failed" '[ "$(count "$tmp/out/summary.json" packed)" = 10 ] && [ "$(count "$tmp/out/summary.json" failed)" = 1 ]'
check "the failure names the file" 'grep -q "broken.obj" "$tmp/e1" && grep -q "\"error\": \".*broken.obj" "$tmp/out/summary.json"'
check "the CSV has a header and 11 rows" '[ "$(wc -l <"$tmp/out/summary.csv")" = 12 ] && head -1 "$tmp/out/summary.csv" | grep -q "status,cache_hit,error"'
check "the CSV carries sizes and errors" 'grep -q ",packed,0,,[0-9]*,[0-9]*,[0-9]*,[0-9]*,1,[0-9]*,0\.000[0-9]" "$tmp/out/summary.csv"'
check "outputs mirror the inputs' folders" '[ -s "$tmp/out/asset000.packed.glb" ] && [ -s "$tmp/out/sub/asset009.packed.glb" ] && [ ! -e "$tmp/out/broken.packed.glb" ]'
cp -r "$tmp/out" "$tmp/first"

# Second run: every good asset from the cache, the same bytes.
"$bin" batch --manifest "$tmp/in/manifest.txt" -o "$tmp/out" --jobs 2 "${opts[@]}" >"$tmp/o2" 2>"$tmp/e2"
check "second run: 10 from the cache" '[ "$(count "$tmp/out/summary.json" cached)" = 10 ] && [ "$(count "$tmp/out/summary.json" packed)" = 0 ]'
check "second run: cache_hit in the CSV" '[ "$(grep -c ",cached,1," "$tmp/out/summary.csv")" = 10 ]'
check "second run: the same outputs" 'same_outputs "$tmp/first" "$tmp/out"'

# One changed input: exactly that one recomputed.
cp "$tmp/in/asset007.obj" "$tmp/in/asset003.obj"
"$bin" batch --manifest "$tmp/in/manifest.txt" -o "$tmp/out" --jobs 2 "${opts[@]}" >"$tmp/o3" 2>"$tmp/e3"
check "a changed input is packed again, alone" '[ "$(count "$tmp/out/summary.json" packed)" = 1 ] && [ "$(count "$tmp/out/summary.json" cached)" = 9 ] && grep -q ",asset003.packed.glb,packed,0," "$tmp/out/summary.csv"'
check "the changed output is replaced" '! cmp -s "$tmp/first/asset003.packed.glb" "$tmp/out/asset003.packed.glb"'
cp -r "$tmp/out" "$tmp/ref"
rm -f "$tmp/in/broken.obj"
grep -v broken "$tmp/in/manifest.txt" >"$tmp/in/good.txt"

# --jobs 1 and a fresh cache: the same bytes as --jobs 2.
"$bin" batch --manifest "$tmp/in/good.txt" -o "$tmp/j1" --jobs 1 "${opts[@]}" >/dev/null 2>&1
check "--jobs 1 succeeds" '[ $? = 0 ]'
check "--jobs 1 and --jobs 2 write the same bytes" 'same_outputs "$tmp/j1" "$tmp/ref"'

# Killed with SIGKILL half-way, then restarted: nothing partial, finished assets not redone.
"$src/tests/tools/batch/make_assets.sh" "$tmp/many" 24
"$bin" batch "$tmp"/many/*.obj -o "$tmp/whole" --jobs 2 "${opts[@]}" >/dev/null 2>&1
"$bin" batch "$tmp"/many/*.obj -o "$tmp/killed" --jobs 2 "${opts[@]}" >/dev/null 2>&1 &
bg=$!
for _ in $(seq 1200); do
  [ "$(ls "$tmp/killed" 2>/dev/null | grep -c 'packed.glb$')" -ge 8 ] && break
  sleep 0.05
done
kill -9 "$bg"
wait "$bg" 2>/dev/null
bg=
done_before=$(ls "$tmp/killed" | grep -c 'packed.glb$')
check "killed half-way ($done_before of 24 done)" '[ "$done_before" -ge 1 ] && [ "$done_before" -lt 24 ]'
partial=0
for f in "$tmp"/killed/*.packed.glb; do cmp -s "$f" "$tmp/whole/$(basename "$f")" || partial=1; done
check "every output present after the kill is complete" '[ $partial = 0 ]'
# The cache is shared by shards and hosts: only temporaries over an hour old are a dead run's.
mkdir -p "$tmp/killed/.hullpack-cache/objects/00"
touch -d '2 hours ago' "$tmp/killed/.hullpack-cache/objects/00/old.glb.tmp-1-1"
touch "$tmp/killed/.hullpack-cache/objects/00/fresh.glb.tmp-1-2"
"$bin" batch "$tmp"/many/*.obj -o "$tmp/killed" --jobs 2 "${opts[@]}" >/dev/null 2>&1
check "the restarted run succeeds" '[ $? = 0 ]'
check "the restart redoes no finished asset" '[ "$(count "$tmp/killed/summary.json" cached)" -ge "$done_before" ]'
check "the restart gives the uninterrupted run's outputs" 'same_outputs "$tmp/whole" "$tmp/killed"'
check "no temporary output is left" \
  '[ -z "$(find "$tmp/killed" -path "*/.hullpack-cache" -prune -o -name "*.tmp-*" -print)" ]'
check "the cache's old temporaries are removed, fresh ones kept" \
  '[ ! -e "$tmp/killed/.hullpack-cache/objects/00/old.glb.tmp-1-1" ] &&
   [ -e "$tmp/killed/.hullpack-cache/objects/00/fresh.glb.tmp-1-2" ]'

# SIGTERM (Ctrl-C, scancel, a Slurm time limit): a summary of what was done, exit 128+15.
"$bin" batch "$tmp"/many/*.obj -o "$tmp/stopped" --jobs 2 "${opts[@]}" >"$tmp/o7" 2>&1 &
bg=$!
for _ in $(seq 1200); do
  [ "$(ls "$tmp/stopped" 2>/dev/null | grep -c 'packed.glb$')" -ge 4 ] && break
  sleep 0.05
done
kill -TERM "$bg"
wait "$bg"
rc=$?
bg=
check "SIGTERM: exit 143 (got $rc)" '[ $rc = 143 ]'
check "SIGTERM: the summary lists every asset, some not done" '[ "$(grep -c "\"input\":" "$tmp/stopped/summary.json")" = 24 ] && [ "$(count "$tmp/stopped/summary.json" cancelled)" -ge 1 ]'
"$bin" batch "$tmp"/many/*.obj -o "$tmp/stopped" --jobs 2 "${opts[@]}" >/dev/null 2>&1
check "SIGTERM: the next run finishes the batch" '[ $? = 0 ] && same_outputs "$tmp/whole" "$tmp/stopped"'

# Shards run apart and merged: every asset once, the same bytes.
for k in 0 1 2; do
  "$bin" batch "$tmp"/many/*.obj -o "$tmp/sharded" --shard $k/3 --cache "$tmp/whole/.hullpack-cache" \
    "${opts[@]}" >/dev/null 2>&1
done
"$bin" batch --merge 3 -o "$tmp/sharded" >"$tmp/o4" 2>&1
check "merge exits 0" '[ $? = 0 ]'
check "the merged summary lists all 24 assets in order" '[ "$(grep -c "\"input\":" "$tmp/sharded/summary.json")" = 24 ] && [ "$(cut -d, -f1 "$tmp/sharded/summary.csv" | tail -n +2 | tr "\n" " ")" = "$(seq -s " " 0 23) " ]'
check "shards from a shared cache: the same bytes" 'same_outputs "$tmp/whole" "$tmp/sharded"'
rm "$tmp/sharded/.hullpack-batch/summary-1-of-3.json"
"$bin" batch --merge 3 -o "$tmp/sharded" >"$tmp/o5" 2>&1
check "merge fails when a shard is missing" '[ $? = 1 ] && grep -q "shard 1 of 3" "$tmp/o5"'

# Usage mistakes exit 64.
"$bin" batch -o "$tmp/x" >/dev/null 2>&1
check "no inputs: 64" '[ $? = 64 ]'
"$bin" batch "$tmp/many/asset000.obj" "$tmp/many/asset000.obj" -o "$tmp/x" >/dev/null 2>"$tmp/e6"
check "an input twice: 64" '[ $? = 64 ] && grep -q "listed twice" "$tmp/e6"'
"$bin" batch "$tmp/many/asset000.obj" -o "$tmp/x" --shard 3/3 >/dev/null 2>&1
check "--shard 3/3: 64" '[ $? = 64 ]'

# pack --cache: an OBJ with a material library and a texture; changing either recomputes.
mkdir "$tmp/tex"
printf 'mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >"$tmp/tex/quad.obj"
printf 'newmtl m\nKd 1 0 0\nmap_Kd red.png\n' >"$tmp/tex/quad.mtl"
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\000\000\001\000\000\000\001\010\002\000\000\000\220\167\123\336\000\000\000\014\111\104\101\124\170\234\143\370\317\300\000\000\003\001\001\000\311\376\222\357\000\000\000\000\111\105\116\104\256\102\140\202' >"$tmp/tex/red.png"
pack_cached() {  # pack_cached NAME: packs quad.obj through the cache, report in NAME.json
  "$bin" pack "$tmp/tex/quad.obj" -o "$tmp/$1.glb" --report "$tmp/$1.json" --cache "$tmp/pc" --hulls none --quiet >/dev/null 2>&1
}
pack_cached p1
check "pack --cache: a miss first" 'grep -q "\"cache_hit\": false" "$tmp/p1.json" && grep -q "\"images_embedded\": 1" "$tmp/p1.json"'
pack_cached p2
check "pack --cache: then a hit, the same bytes" 'grep -q "\"cache_hit\": true" "$tmp/p2.json" && cmp -s "$tmp/p1.glb" "$tmp/p2.glb"'
printf '\n' >>"$tmp/tex/red.png"
pack_cached p3
check "pack --cache: a changed texture is a miss" 'grep -q "\"cache_hit\": false" "$tmp/p3.json"'
printf 'newmtl m\nKd 0 1 0\nmap_Kd red.png\n' >"$tmp/tex/quad.mtl"
pack_cached p4
check "pack --cache: a changed material library is a miss" 'grep -q "\"cache_hit\": false" "$tmp/p4.json"'
pack_cached p5
check "pack --cache: unchanged again, a hit" 'grep -q "\"cache_hit\": true" "$tmp/p5.json" && cmp -s "$tmp/p4.glb" "$tmp/p5.glb"'
"$bin" pack "$tmp/tex/quad.obj" -o "$tmp/p6.glb" --report "$tmp/p6.json" --cache "$tmp/pc" --hulls none --quiet --max-error 0.001 >/dev/null 2>&1
check "pack --cache: other options are a miss" 'grep -q "\"cache_hit\": false" "$tmp/p6.json"'

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
