# Shared by the command-line tests (sourced): run a program, check its exit status and output.
#   run NAME EXPECTED_EXIT PATTERN -- command...
# EXPECTED_EXIT 0 means success; any other value is the exact status wanted. PATTERN (may be empty)
# must appear in stdout or stderr. A non-zero status must come with exactly one line on stderr
# (the convention of every program), except for status 1 (a run that failed on its input may say
# more). The output of the last run is in $tmp/out and $tmp/err.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0

fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}

pass() { passes=$((passes + 1)); }

run() {
  local name=$1 want=$2 pattern=$3
  shift 4
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  if [ "$rc" -ge 128 ]; then fail "$name: crashed (exit $rc)"; return; fi
  if [ "$rc" -ne "$want" ]; then
    fail "$name: exit $rc, expected $want: $(head -c 400 "$tmp/err")"
    return
  fi
  if [ -n "$pattern" ] && ! grep -q -- "$pattern" "$tmp/out" "$tmp/err"; then
    fail "$name: output lacks '$pattern': $(head -c 400 "$tmp/err")"
    return
  fi
  if [ "$want" -gt 1 ] && [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
    fail "$name: expected a one-line error, got: $(cat "$tmp/err")"
    return
  fi
  pass
}

# The conventions every program follows: --help/-h on stdout with exit 0, --version with exit 0,
# usage errors with exit 64 and one line.
check_conventions() {  # check_conventions NAME command...
  local name=$1
  shift
  run "$name-help" 0 "usage: $name" -- "$@" --help
  [ -s "$tmp/err" ] && fail "$name --help wrote to stderr"
  run "$name-h" 0 "usage: $name" -- "$@" -h
  run "$name-version" 0 "$name.* [0-9][0-9]*\.[0-9][0-9]*\.[0-9]" -- "$@" --version
  run "$name-unknown-option" 64 "unknown option '--no-such-option'" -- "$@" --no-such-option
}

finish() {
  echo "$passes passed, $failures failed"
  [ "$failures" -eq 0 ]
}
