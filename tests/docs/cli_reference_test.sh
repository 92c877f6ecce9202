#!/usr/bin/env bash
# docs/cli-reference.md against the programs: every option a program's --help lists is documented
# in the program's section, every documented option is in its --help, and every section belongs to
# a listed program (tests/docs/CMakeLists.txt). -h, --help and --version are documented once for
# all programs, so they are left out of the comparison.
# usage: cli_reference_test.sh DOC ENTRY...
#   ENTRY: "SECTION|PROGRAM_PATH|SUBCOMMAND"; an empty PROGRAM_PATH (a program this build does not
#   have) checks only that the section exists.
set -u
doc=$1
shift
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
[ -f "$doc" ] || { echo "FAIL $doc: missing"; exit 1; }

# Option names of a --help text: the lines of the "options:" block that start with two spaces and
# a dash; on each, the spellings before the help text, without their value names.
help_options() {
  awk '/^options:$/ { on = 1; next } on && /^$/ { on = 0 } on && /^  -/ {
         line = substr($0, 3); sub(/  .*/, "", line); n = split(line, names, ", ");
         for (i = 1; i <= n; i++) { split(names[i], w, " "); print w[1] } }' |
    grep -vxE -- '-h|--help|--version' | sort -u
}

# Option names documented in SECTION: the backquoted `-name` tokens of the first cell of the table
# rows in the part of the file under "## `SECTION`".
doc_options() {
  awk -v heading="## \`$1\`" '$0 == heading { on = 1; next } /^## / { on = 0 } on' "$doc" |
    grep '^| `-' | sed 's/^| //; s/ | .*//' | grep -oE '`--?[A-Za-z0-9][-A-Za-z0-9]*`' | tr -d '`' |
    grep -vxE -- '-h|--help|--version' | sort -u
}

sections=()
for entry in "$@"; do
  IFS='|' read -r section path subcommand <<<"$entry"
  sections+=("$section")
  if ! grep -qxF "## \`$section\`" "$doc"; then
    fail "$section: no section '## \`$section\`' in $doc"
    continue
  fi
  [ -n "$path" ] || { echo "skip $section: not built here (section present)"; continue; }
  # shellcheck disable=SC2086
  help=$("$path" $subcommand --help) || { fail "$section: --help exits $?"; continue; }
  help_list=$(printf '%s\n' "$help" | help_options)
  doc_list=$(doc_options "$section")
  undocumented=$(comm -23 <(printf '%s\n' "$help_list") <(printf '%s\n' "$doc_list") | grep .)
  gone=$(comm -13 <(printf '%s\n' "$help_list") <(printf '%s\n' "$doc_list") | grep .)
  [ -z "$undocumented" ] || fail "$section: in --help, not in $doc: $(echo $undocumented)"
  [ -z "$gone" ] || fail "$section: in $doc, not in --help: $(echo $gone)"
  [ -z "$undocumented$gone" ] && echo "ok $section: $(printf '%s\n' "$help_list" | grep -c .) options"
done
# Sections of programs that are not in the list (a removed program, or one added without a line).
while IFS= read -r heading; do
  name=${heading#'## `'}
  name=${name%'`'}
  printf '%s\n' "${sections[@]}" | grep -qxF -- "$name" ||
    fail "$doc documents '$name', which is not in the list of programs (tests/docs/CMakeLists.txt)"
done < <(grep -E '^## `[^`]+`$' "$doc")
echo "$failures failed"
[ "$failures" -eq 0 ]
