#!/usr/bin/env bash
# Assets as Draco and gltfpack publish them (samples/compressed/, made from samples the project
# holds) read like their sources: same triangles, bounds and UV ranges, and they pack.
# usage: compressed_inputs_test.sh HULLPACK_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# The line of `hullpack info` that starts with $2 (after indentation).
info_line() { "$bin" info "$1" | sed -n "s/^ *$2/&/p" | head -1; }

# min/max of each column of the OBJ lines that start with $2 ("v" or "vt"), rounded to 3 decimals.
ranges() {
  awk -v tag="$2" '$1 == tag { for (i = 2; i <= NF; ++i) { if (!(i in lo) || $i < lo[i]) lo[i] = $i;
                                                          if (!(i in hi) || $i > hi[i]) hi[i] = $i } }
    END { for (i = 2; i in lo; ++i) printf "%.3f %.3f ", lo[i], hi[i]; print "" }' "$1"
}

# Draco (glTF-Transform, edgebreaker) of the torus sample: the torus's triangles and bounds.
draco=$src/samples/compressed/torus_draco.glb
want=$(info_line "$src/samples/torus.obj" "meshes 1, triangles")
got=$(info_line "$draco" "meshes 1, triangles")
[ "${want%%, vertices*}" = "${got%%, vertices*}" ] || fail "draco triangles: '$got' against '$want'"
"$bin" unpack "$draco" -o "$tmp/draco.obj" >/dev/null || fail "draco unpack"
# Draco quantized the positions at 14 bits: equal to 3 decimals on a torus of size ~2.
[ "$(ranges "$tmp/draco.obj" v)" = "$(ranges "$src/samples/torus.obj" v)" ] ||
  fail "draco bounds: $(ranges "$tmp/draco.obj" v) against $(ranges "$src/samples/torus.obj" v)"
"$bin" pack "$draco" -o "$tmp/draco_packed.glb" --quiet >/dev/null || fail "draco pack"

# gltfpack -cc of the Kenney coin: meshopt-compressed, quantized, and its UVs dequantized by a
# KHR_texture_transform that the reader bakes in, so they span what the original's do.
meshopt=$src/samples/compressed/kenney_block_coin_gltfpack.glb
original=$src/samples/assets/kenney_block_coin.glb
want=$(info_line "$original" "meshes 1, triangles")
got=$(info_line "$meshopt" "meshes 1, triangles")
[ "${want%%, vertices*}" = "${got%%, vertices*}" ] || fail "meshopt triangles: '$got' against '$want'"
if "$bin" info "$meshopt" | grep -q "KHR_texture_transform"; then
  fail "meshopt: KHR_texture_transform reported as not kept"
fi
"$bin" unpack "$meshopt" -o "$tmp/meshopt.obj" >/dev/null || fail "meshopt unpack"
"$bin" pack "$original" -o "$tmp/original_packed.glb" --quiet >/dev/null || fail "original pack"
"$bin" unpack "$tmp/original_packed.glb" -o "$tmp/original.obj" >/dev/null || fail "original unpack"
[ "$(ranges "$tmp/meshopt.obj" vt)" = "$(ranges "$tmp/original.obj" vt)" ] ||
  fail "meshopt UV ranges: $(ranges "$tmp/meshopt.obj" vt) against $(ranges "$tmp/original.obj" vt)"
"$bin" pack "$meshopt" -o "$tmp/meshopt_packed.glb" --quiet >/dev/null || fail "meshopt pack"

# The same two files as a .gltf whose buffer 0 is a .bin beside it (glTF-Transform's .gltf output):
# the streams are read from the .bin, and the file reads like its GLB. With "second", the streams
# are in a second buffer file (glTF-Transform's `partition` writes one .bin per buffer): a small
# first buffer is put in front, and every buffer index moves up by one.
split_glb() {  # GLB OUT.gltf BIN_NAME [second]
  python3 - "$@" <<'PY'
import json, struct, sys, os
glb, gltf, bin_name = sys.argv[1:4]
second = len(sys.argv) > 4 and sys.argv[4] == "second"
data = open(glb, "rb").read()
at, chunks = 12, {}
while at + 8 <= len(data):
    length, kind = struct.unpack_from("<II", data, at)
    chunks[kind] = data[at + 8:at + 8 + length]
    at += 8 + length
doc = json.loads(chunks[0x4E4F534A])
doc["buffers"][0]["uri"] = bin_name.replace(" ", "%20")
folder = os.path.dirname(gltf)
if second:
    doc["buffers"].insert(0, {"uri": "first.bin", "byteLength": 4})
    for view in doc.get("bufferViews", []):
        view["buffer"] += 1
        meshopt = view.get("extensions", {}).get("EXT_meshopt_compression")
        if meshopt is not None:
            meshopt["buffer"] += 1
    open(os.path.join(folder, "first.bin"), "wb").write(bytes(4))
open(gltf, "w").write(json.dumps(doc))
open(os.path.join(folder, bin_name), "wb").write(chunks[0x004E4942])
PY
}
for glb in "$draco" "$meshopt"; do
  name=$(basename "$glb" .glb)
  want=$(info_line "$glb" "meshes")
  split_glb "$glb" "$tmp/$name.gltf" "$name data.bin" || { fail "$name: cannot split"; continue; }
  got=$(info_line "$tmp/$name.gltf" "meshes")
  [ -n "$got" ] && [ "$want" = "$got" ] || fail "$name.gltf: '$got' against the GLB's '$want'"
  "$bin" pack "$tmp/$name.gltf" -o "$tmp/${name}_gltf_packed.glb" --quiet >/dev/null || fail "$name.gltf pack"
  mkdir -p "$tmp/second_$name"
  split_glb "$glb" "$tmp/second_$name/$name.gltf" "$name streams.bin" second ||
    { fail "$name: cannot split into two buffers"; continue; }
  got=$(info_line "$tmp/second_$name/$name.gltf" "meshes")
  [ -n "$got" ] && [ "$want" = "$got" ] ||
    fail "$name.gltf, streams in buffer 1: '$got' against the GLB's '$want'"
  "$bin" pack "$tmp/second_$name/$name.gltf" -o "$tmp/${name}_second_packed.glb" --quiet \
    >/dev/null || fail "$name.gltf, streams in buffer 1: pack"
  cmp -s "$tmp/${name}_gltf_packed.glb" "$tmp/${name}_second_packed.glb" ||
    fail "$name.gltf: the streams in buffer 1 pack to other bytes than in buffer 0"
done
# A missing buffer file is an error that names it.
rm "$tmp/second_$(basename "$draco" .glb)/$(basename "$draco" .glb) streams.bin"
if "$bin" info "$tmp/second_$(basename "$draco" .glb)/$(basename "$draco" .glb).gltf" >/dev/null 2>"$tmp/err"; then
  fail "a missing second buffer file was not an error"
else
  grep -q "streams.bin" "$tmp/err" || fail "the missing buffer file is not named: $(cat "$tmp/err")"
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures checks failed"
  exit 1
fi
echo "compressed inputs: all checks passed"
