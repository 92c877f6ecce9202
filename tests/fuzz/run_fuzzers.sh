#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan+UBSan) and runs each for a fixed time from its seed
# corpus, one per core at a time. Any crash, leak, sanitizer report or timeout fails the run; the
# reproducer is kept in <build>/artifacts/ so it can become a regression test.
# usage: tests/fuzz/run_fuzzers.sh [SECONDS_PER_TARGET|seeds]   (default: $HULLPACK_FUZZ_SECONDS or 60)
# env:   HULLPACK_FUZZ_BUILD_DIR (build-fuzz; ./setup.sh test passes its sanitized tree, build-sanitize),
#        HULLPACK_FUZZ_JOBS (targets at a time; default nproc)
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-${HULLPACK_FUZZ_SECONDS:-60}}
build=${HULLPACK_FUZZ_BUILD_DIR:-build-fuzz}
if ! command -v clang++ >/dev/null; then
  echo "run_fuzzers: clang++ not found (setup.sh installs clang)" >&2
  exit 1
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DHULLPACK_FUZZ=ON -DHULLPACK_BUILD_TESTS=OFF >/dev/null
fi
targets=(o3dgc_decoder_fuzzer packed_glb_fuzzer obj_reader_fuzzer off_reader_fuzzer wrl_reader_fuzzer ply_reader_fuzzer
  threemf_reader_fuzzer)
# Only the fuzzers and the two programs that make the seeds (not every tool of the fuzz build).
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}" test_o3dgc hullpack >/dev/null
mkdir -p "$build/artifacts"
# Seeds for the binary formats come from this build's own encoder, so they follow the stream format.
gen=$build/generated-seeds
mkdir -p "$gen/o3dgc_decoder_fuzzer" "$gen/packed_glb_fuzzer"
cp samples/torus.obj "$gen/torus.obj"
cp tests/fuzz/seeds/obj_reader_fuzzer/tetra.obj "$gen/tetra.obj"
enc="$build/tools/test_o3dgc/test_o3dgc"
pack() { "$build/tools/hullpack/hullpack" pack "$gen/tetra.obj" --force --quiet --resolution 10000 "$@" >/dev/null; }
# The torus exercises the connectivity coder; the tetrahedron (groups, UVs, normals) keeps inputs small.
"$enc" -c -i "$gen/torus.obj" -st binary -qc 8 >/dev/null && mv "$gen/torus.s3d" "$gen/o3dgc_decoder_fuzzer/binary.s3d"
"$enc" -c -i "$gen/torus.obj" -st ascii -qc 8 >/dev/null && mv "$gen/torus.s3d" "$gen/o3dgc_decoder_fuzzer/ascii.s3d"
"$enc" -c -i "$gen/tetra.obj" -st binary -qc 10 -keep >/dev/null && mv "$gen/tetra.s3d" "$gen/o3dgc_decoder_fuzzer/tetra_keep.s3d"
"$enc" -c -i "$gen/tetra.obj" -st ascii -qc 10 >/dev/null && mv "$gen/tetra.s3d" "$gen/o3dgc_decoder_fuzzer/tetra_ascii.s3d"
# A 4489-vertex grid jittered in x, y and z: past the size where residual signs and low bits are read
# raw, with residuals large enough for the encoder to send class shifts (attribute_coder.h).
awk 'function r() { s = (s * 1103515245 + 12345) % 2147483648; return 0.008 * (s / 2147483648 - 0.5) }
  BEGIN { n = 66; s = 7
    for (j = 0; j <= n; ++j) for (i = 0; i <= n; ++i) printf "v %.6f %.6f %.6f\n", i / n + r(), j / n + r(), r()
    for (j = 0; j < n; ++j) for (i = 0; i < n; ++i) { a = j * (n + 1) + i + 1
      printf "f %d %d %d\nf %d %d %d\n", a, a + 1, a + n + 2, a, a + n + 2, a + n + 1 } }' >"$gen/rough_grid.obj"
"$enc" -c -i "$gen/rough_grid.obj" -st binary -qc 14 >/dev/null && mv "$gen/rough_grid.s3d" "$gen/o3dgc_decoder_fuzzer/rough_grid.s3d"
# The rough grid and the tetrahedron again, coded in vertex id order (test_o3dgc -fast).
"$enc" -c -i "$gen/rough_grid.obj" -st binary -qc 14 -fast >/dev/null && mv "$gen/rough_grid.s3d" "$gen/o3dgc_decoder_fuzzer/rough_grid_fast.s3d"
"$enc" -c -i "$gen/tetra.obj" -st binary -qc 10 -fast >/dev/null && mv "$gen/tetra.s3d" "$gen/o3dgc_decoder_fuzzer/tetra_fast.s3d"
# Boxes on a design grid: the encoder writes format 1.2 with modelled low bits (entropy.h).
awk 'BEGIN { n = 0
  for (j = 0; j < 4; ++j) for (i = 0; i < 5; ++i) { h = 0.7 * (2 + (i + 2 * j) % 5)
    for (c = 0; c < 8; ++c) printf "v %.4f %.4f %.4f\n", 0.7 * (3 * i + 2 * (c % 2)), 0.7 * (3 * j + 2 * (int(c / 2) % 2)), (c >= 4) ? h : 0
    split("1 3 2 2 3 4 5 6 7 6 8 7 1 2 5 2 6 5 3 7 4 4 7 8 1 5 3 3 5 7 2 4 6 4 8 6", f, " ")
    for (t = 0; t < 12; ++t) printf "f %d %d %d\n", n + f[3 * t + 1], n + f[3 * t + 2], n + f[3 * t + 3]
    n += 8 } }' >"$gen/grid_blocks.obj"
"$enc" -c -i "$gen/grid_blocks.obj" -st binary -qc 14 >/dev/null && mv "$gen/grid_blocks.s3d" "$gen/o3dgc_decoder_fuzzer/grid_blocks.s3d"
# Packed GLBs stay small (a few KB): the fuzzer's speed is set by the JSON text it scans.
rm -f "$gen/packed_glb_fuzzer/"*.glb
pack -o "$gen/packed_glb_fuzzer/hulls.glb" --max-hulls 2
pack -o "$gen/packed_glb_fuzzer/khr_ascii.glb" --max-hulls 1 --physics khr --ascii
pack -o "$gen/packed_glb_fuzzer/fallback.glb" --hulls none --fallback --keep-order
[ "$seconds" = seeds ] && exit 0  # build and make the seeds only (what tests/fuzz/campaign.sh needs)
# Targets run side by side, HULLPACK_FUZZ_JOBS at a time (default: one per core), each one process.
jobs=${HULLPACK_FUZZ_JOBS:-$(nproc)}
run_one() {
  local target=$1 seeds=() dir
  for dir in "tests/fuzz/seeds/$target" "tests/fuzz/regressions/$target" "$gen/$target"; do [ -d "$dir" ] && seeds+=("$dir"); done
  local corpus=$build/corpus/$target log=$build/$target.log
  mkdir -p "$corpus"
  if "$build/tools/fuzz/$target" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1 >"$log" 2>&1; then
    local runs
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz $target: ok, $runs executions in ${seconds}s"
  else
    # One write, so the report of a failing target is not interleaved with another's line.
    printf 'fuzz %s: FAILED (see %s)\n%s\n' "$target" "$log" "$(tail -30 "$log")"
    return 1
  fi
}
status=0
pids=()
for target in "${targets[@]}"; do
  run_one "$target" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit $status
