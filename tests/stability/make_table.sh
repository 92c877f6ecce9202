#!/usr/bin/env bash
# Prints the stability suite's case table (docs/stability.md) from a real run of the suite:
# one Markdown row per case, as each test prints it.
# usage: tests/stability/make_table.sh [BUILD_DIR]   (default: build; runs the heavy case too)
set -euo pipefail
build=${1:-build}
echo '| case | input | expected: decompose / codec / pack | promised: codec per axis / pack | decompose (vhacd) | o3dgc codec (keep order, 14 bits) | mesh codec (pipeline) | pack + read back | peak RSS (MB) |'
echo '|---|---|---|---|---|---|---|---|---|'
for exe in "$build/tests/stability/stability_tests" "$build/tests/stability/stability_heavy_tests"; do
  [ -x "$exe" ] || { echo "make_table: $exe not built" >&2; exit 1; }
  # One process per case, as ctest runs them, so each row's peak RSS is the case's own.
  for test in $("$exe" --gtest_list_tests | awk '/^ / {print prefix $1} /^[^ ]/ {prefix = $1}'); do
    if ! out=$("$exe" --gtest_filter="$test"); then
      echo "make_table: $test FAILED" >&2
      failed=1
    fi
    grep '^| ' <<<"$out" || true
  done
done
exit ${failed:-0}
