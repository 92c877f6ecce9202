#!/usr/bin/env bash
# A long fuzzing campaign: runs each named target until it has executed TOTAL inputs, in chunks of
# CHUNK executions (so a crash or a stop loses at most one chunk), one process at a time, at the
# lowest CPU priority. The executions of every chunk are appended to
# $build/campaign/<target>.runs ("<date> <executions> <seconds> <exit status>"); a later call
# continues from the sum already there (a chunk stopped with SIGTERM still prints and counts its
# executions). A failing chunk stops that target and leaves the reproducer in $build/artifacts/.
# usage: tests/fuzz/campaign.sh TOTAL [TARGET...]      (default targets: all five, one after another;
#        start one campaign per target to run them side by side)
# env:   HULLPACK_FUZZ_BUILD_DIR (build-fuzz), CHUNK (1000000), MAX_LEN (per target default below)
# The fuzz build must exist: tests/fuzz/run_fuzzers.sh 1 configures, builds and makes the seeds.
set -uo pipefail
cd "$(dirname "$0")/../.."
total=${1:?usage: campaign.sh TOTAL [TARGET...]}
shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(o3dgc_decoder_fuzzer off_reader_fuzzer wrl_reader_fuzzer obj_reader_fuzzer packed_glb_fuzzer)
build=${HULLPACK_FUZZ_BUILD_DIR:-build-fuzz}
chunk=${CHUNK:-1000000}
mkdir -p "$build/campaign" "$build/artifacts"

max_len_for() {
  case "$1" in
    packed_glb_fuzzer) echo 4096 ;;  # small GLBs: the JSON scan dominates, and big ones add no paths
    *) echo 8192 ;;
  esac
}

for target in "${targets[@]}"; do
  exe=$build/tools/fuzz/$target
  [ -x "$exe" ] || { echo "campaign: $exe not built" >&2; exit 1; }
  ledger=$build/campaign/$target.runs
  touch "$ledger"
  corpus=$build/corpus/$target
  mkdir -p "$corpus"
  seeds=()
  for dir in "tests/fuzz/seeds/$target" "tests/fuzz/regressions/$target" "$build/generated-seeds/$target"; do [ -d "$dir" ] && seeds+=("$dir"); done
  while :; do
    done_runs=$(awk '{s += $2} END {print s + 0}' "$ledger")
    [ "$done_runs" -ge "$total" ] && break
    log=$build/campaign/$target.last.log
    start=$(date +%s)
    nice -n 19 "$exe" "$corpus" "${seeds[@]}" -runs="$chunk" -max_len="${MAX_LEN:-$(max_len_for "$target")}" \
      -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/$target-" \
      -print_final_stats=1 >"$log" 2>&1
    rc=$?
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
    echo "$(date -u +%FT%TZ) ${runs:-0} $(( $(date +%s) - start )) $rc" >>"$ledger"
    if [ $rc -ne 0 ]; then
      cp "$log" "$build/campaign/$target.failed.$(date +%s).log"
      echo "campaign $target: FAILED after $done_runs executions (see $build/campaign/)" >&2
      break
    fi
  done
  echo "campaign $target: $(awk '{s += $2} END {print s + 0}' "$ledger") executions"
done
