#!/usr/bin/env bash
# Builds decoder_ab (see decoder_ab.cc) from two source trees of this repository:
#   tools/bench/decoder_ab.sh TREE_A TREE_B OUT
# e.g. git worktree add /tmp/base HEAD --detach; tools/bench/decoder_ab.sh /tmp/base . /tmp/ab
#      /tmp/ab 31 bunny.s3d igea.s3d
# Both builds use the project's Release flags (-O3 -DNDEBUG); build B's symbols are renamed to
# namespace o3dgc_alt, so that the two link into one program.
set -euo pipefail
if [ $# -ne 3 ]; then
  echo "usage: $0 TREE_A TREE_B OUT" >&2
  exit 64
fi
a=$(cd "$1" && pwd)
b=$(cd "$2" && pwd)
out=$3
here=$(cd "$(dirname "$0")" && pwd)
cxx=${CXX:-g++}
flags="-O3 -DNDEBUG -std=c++17"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pids=()
for src in "$a"/o3dgc/src/*.cc; do
  $cxx $flags -I"$a/o3dgc/include" -I"$a/o3dgc/src" -c "$src" -o "$tmp/a_$(basename "$src" .cc).o" &
  pids+=($!)
done
for src in "$b"/o3dgc/src/*.cc; do
  $cxx $flags -Do3dgc=o3dgc_alt -I"$b/o3dgc/include" -I"$b/o3dgc/src" -c "$src" -o "$tmp/b_$(basename "$src" .cc).o" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done  # a failed compile stops the script here
# The command-line parser and the version header CMake would generate.
mkdir -p "$tmp/generated/common"
version=$(sed -n 's/^project(hullpack VERSION \([0-9.]*\).*/\1/p' "$here/../../CMakeLists.txt")
sed "s/@PROJECT_VERSION@/$version/" "$here/../common/version.h.in" >"$tmp/generated/common/version.h"
$cxx $flags -I"$a/o3dgc/include" -I"$here/.." -I"$tmp/generated" "$here/decoder_ab.cc" \
  "$here/../common/cli_args.cc" "$tmp"/*.o -o "$out"
