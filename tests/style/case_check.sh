#!/usr/bin/env bash
# Fails when two tracked paths differ only in case: one would overwrite the other on a
# case-insensitive file system (macOS, Windows checkouts).
set -euo pipefail
cd "$1"
clashes=$(git ls-files | tr '[:upper:]' '[:lower:]' | sort | uniq -d)
if [ -n "$clashes" ]; then
  echo "paths that differ only in case:"; echo "$clashes"; exit 1
fi
echo "no two tracked paths differ only in case"
