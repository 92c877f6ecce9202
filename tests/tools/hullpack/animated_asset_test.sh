#!/usr/bin/env bash
# An animated game character (samples/assets/kenney_character.glb, 4 clips) keeps its clips through
# pack and unpack, with the tracks that hold their node at rest left out and said so.
# usage: animated_asset_test.sh HULLPACK_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# The number after "animations " in `hullpack info`.
animations() { "$bin" info "$1" | sed -n 's/.*animations \([0-9]*\).*/\1/p' | head -1; }

character=$src/samples/assets/kenney_character.glb
[ "$(animations "$character")" = 4 ] || fail "the source reads with $(animations "$character") clips"

"$bin" pack "$character" -o "$tmp/packed.glb" >"$tmp/report.txt" 2>&1 || fail "pack: $(cat "$tmp/report.txt")"
[ "$(animations "$tmp/packed.glb")" = 4 ] || fail "the packed file has $(animations "$tmp/packed.glb") clips"
grep -q "animation key frames [0-9]* -> [0-9]* bytes" "$tmp/report.txt" ||
  fail "the report does not give the key frames' sizes: $(cat "$tmp/report.txt")"
grep -q "animation tracks that hold their node at rest" "$tmp/report.txt" ||
  fail "the report does not say which tracks were left out: $(cat "$tmp/report.txt")"
"$bin" info "$tmp/packed.glb" | grep -q "not kept:.*animation" &&
  fail "the packed file drops animation data: $("$bin" info "$tmp/packed.glb" | grep 'not kept')"

# Unpacked back to a plain GLB, the clips are still there, and they play on TRS nodes.
"$bin" unpack "$tmp/packed.glb" -o "$tmp/plain.glb" >/dev/null 2>&1 || fail "unpack"
[ "$(animations "$tmp/plain.glb")" = 4 ] || fail "the unpacked file has $(animations "$tmp/plain.glb") clips"
grep -a -q '"animations"' "$tmp/plain.glb" || fail "no animations array in the unpacked JSON"
grep -a -q '"path":"rotation"' "$tmp/plain.glb" || fail "no rotation channel in the unpacked JSON"

# The packed file is smaller than the source even with its clips and hulls.
src_size=$(stat -c %s "$character")
out_size=$(stat -c %s "$tmp/packed.glb")
[ "$out_size" -lt "$src_size" ] || fail "packed $out_size bytes against the source's $src_size"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "ok: 4 clips kept through pack and unpack ($src_size -> $out_size bytes)"
