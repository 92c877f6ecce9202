#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan+UBSan) and runs each for a fixed time from its seed
# corpus. Any crash, leak, sanitizer report or timeout fails the run; the reproducer is kept in
# build-fuzz/artifacts/ so it can become a regression test.
# usage: tests/fuzz/run_fuzzers.sh [SECONDS_PER_TARGET]   (default: $HULLPACK_FUZZ_SECONDS or 60)
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
cmake --build "$build" -j "$(nproc)" >/dev/null
mkdir -p "$build/artifacts"
status=0
for target in $(ls "$build/tools/fuzz/" | grep '_fuzzer$'); do
  seeds=tests/fuzz/seeds/$target
  corpus=$build/corpus/$target
  mkdir -p "$corpus"
  log=$build/$target.log
  if "$build/tools/fuzz/$target" "$corpus" "$seeds" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1 >"$log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz $target: ok, $runs executions in ${seconds}s"
  else
    echo "fuzz $target: FAILED (see $log)"; tail -30 "$log"
    status=1
  fi
done
exit $status
