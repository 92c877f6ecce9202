#!/usr/bin/env bash
# Every path docs/architecture.md names (in backquotes, with a folder and an extension, or ending
# in '/') exists in the tree. Usage: architecture_paths_test.sh SOURCE_DIR
set -u
top=$1
doc=$top/docs/architecture.md
[ -f "$doc" ] || { echo "no $doc"; exit 1; }
failures=0
checked=0
while IFS= read -r path; do
  checked=$((checked + 1))
  if [ ! -e "$top/$path" ]; then
    echo "FAIL: $doc names $path, which does not exist"
    failures=$((failures + 1))
  fi
done < <(grep -oE '`[A-Za-z0-9_./-]+`' "$doc" | tr -d '`' | grep -E '^[A-Za-z0-9_.-]+/([A-Za-z0-9_./-]*\.[a-z]+|[A-Za-z0-9_./-]*/)$' | sort -u)
echo "$checked paths checked, $failures missing"
[ "$checked" -gt 20 ] || { echo "FAIL: too few paths found: is the pattern still right?"; exit 1; }
[ "$failures" -eq 0 ]
