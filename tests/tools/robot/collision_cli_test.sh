#!/usr/bin/env bash
# `hullpack collision`: each format written, relative paths that resolve, and each description
# accepted by its format's checker: check_urdf (liburdfdom-tools), `ign sdf -k` (ignition-tools +
# libsdformat-dev), check_mjcf.py (MuJoCo's XML reference rules); usage errors exit 64; nothing
# is overwritten without --force.
# Usage: collision_cli_test.sh HULLPACK SOURCE_DIR CHECK_URDF IGN
set -u
hullpack=$1 src=$2 check_urdf=$3 ign=$4
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
[ -x "$check_urdf" ] || { echo "check_urdf not found (Debian package liburdfdom-tools)"; exit 1; }
[ -x "$ign" ] || { echo "ign not found (Debian packages ignition-tools libsdformat-dev)"; exit 1; }

input="$work/wheel part.obj"   # a space and a dot: the name must be sanitized
cp "$src/samples/torus.obj" "$input"

for format in urdf mjcf sdf; do
  out="$work/$format"
  "$hullpack" collision "$input" -o "$out" --format $format --resolution 20000 --density 500 \
    --quiet >"$work/$format.log" 2>&1 || { fail "$format: exit $?"; cat "$work/$format.log"; continue; }
  case $format in urdf) desc="$out/wheel_part.urdf" ;; mjcf) desc="$out/wheel_part.xml" ;; sdf) desc="$out/wheel_part.sdf" ;; esac
  [ -f "$desc" ] || { fail "$format: no $desc"; ls -R "$out"; continue; }
  # Every referenced file exists relative to the description; no absolute path.
  refs=$(grep -oE '(filename|file)="[^"]+"|<uri>[^<]+</uri>' "$desc" | sed -E 's/^(filename|file)="//; s/"$//; s/<\/?uri>//g')
  [ -n "$refs" ] || fail "$format: no mesh references"
  for r in $refs; do
    case $r in /*) fail "$format: absolute path $r" ;; esac
    [ -f "$out/$r" ] || fail "$format: $r does not exist beside $desc"
  done
  hulls=$(grep -c '_hull_' "$desc")
  [ "$hulls" -ge 3 ] || fail "$format: expected several hull references, got $hulls"
  case $format in
    urdf)
      # check_urdf exits 0 after some errors (a link it could not read): its log must be clean too.
      "$check_urdf" "$desc" >"$work/check.log" 2>&1 || { fail "check_urdf rejected $desc"; cat "$work/check.log"; }
      grep -qi 'error' "$work/check.log" && { fail "check_urdf reported errors"; cat "$work/check.log"; }
      grep -q "robot name is: wheel_part" "$work/check.log" || fail "check_urdf did not read the robot name"
      ;;
    sdf)
      "$ign" sdf -k "$desc" >"$work/check.log" 2>&1
      grep -q '^Valid\.$' "$work/check.log" || { fail "ign sdf -k rejected $desc"; cat "$work/check.log"; }
      # (ignition-tools' own notice about an optional backtrace library is not about the file)
      grep -v 'libignition-tools-backward' "$work/check.log" | grep -qi 'warning\|error' &&
        { fail "ign sdf -k reported problems"; cat "$work/check.log"; }
      ;;
    mjcf)
      /usr/bin/python3 "$here/check_mjcf.py" "$desc" || fail "check_mjcf.py rejected $desc"
      ;;
  esac
done

# The checkers can fail: a broken URDF and a broken MJCF are rejected.
sed 's/<geometry><mesh filename="[^"]*"\/><\/geometry>/<geometry><\/geometry>/' "$work/urdf/wheel_part.urdf" >"$work/bad.urdf"
"$check_urdf" "$work/bad.urdf" 2>&1 | grep -qi error || fail "check_urdf accepted a collision without geometry"
sed 's/<mass>[^<]*</<mass>heavy</' "$work/sdf/wheel_part.sdf" >"$work/sdf/bad.sdf"
"$ign" sdf -k "$work/sdf/bad.sdf" 2>&1 | grep -q '^Valid\.$' && fail "ign sdf -k accepted a non-numeric mass"
sed 's/maxhullvert="64"/maxhullvert="3"/' "$work/mjcf/wheel_part.xml" >"$work/mjcf/bad.xml"
/usr/bin/python3 "$here/check_mjcf.py" "$work/mjcf/bad.xml" >/dev/null && fail "check_mjcf.py accepted maxhullvert=3"

# An existing description is kept unless --force.
before=$(md5sum <"$work/urdf/wheel_part.urdf")
"$hullpack" collision "$input" -o "$work/urdf" --resolution 20000 --quiet 2>"$work/err.log" && fail "overwrote without --force"
grep -q "exists" "$work/err.log" || fail "no 'exists' message: $(cat "$work/err.log")"
[ "$(md5sum <"$work/urdf/wheel_part.urdf")" = "$before" ] || fail "the description changed"
"$hullpack" collision "$input" -o "$work/urdf" --resolution 20000 --quiet --force >/dev/null || fail "--force failed"

# The output folder is made with its missing parents, as mkdir -p would; a file in the way is an error.
"$hullpack" collision "$input" -o "$work/new/nested" --resolution 20000 --quiet >"$work/nested.log" 2>&1 ||
  fail "missing parents of -o: $(cat "$work/nested.log")"
[ -f "$work/new/nested/wheel_part.urdf" ] || fail "no description under the new folders"
touch "$work/plain_file"
"$hullpack" collision "$input" -o "$work/plain_file/sub" --resolution 20000 --quiet 2>"$work/err.log" &&
  fail "a file where a folder must go was accepted"
grep -q "plain_file" "$work/err.log" || fail "the folder error does not name the path: $(cat "$work/err.log")"

# The vertex cap is respected and checked per format; JSON report.
"$hullpack" collision "$input" -o "$work/cap" --format mjcf --max-hull-vertices 12 --resolution 20000 --json >"$work/cap.json" || fail "--max-hull-vertices 12"
grep -q '"largest_hull_vertices": \([4-9]\|1[0-2]\),' "$work/cap.json" || fail "cap not respected: $(grep largest "$work/cap.json")"
"$hullpack" collision "$input" -o "$work/x" --format urdf --max-hull-vertices 300 >/dev/null 2>&1
[ $? -eq 64 ] || fail "a cap above 255 for URDF is not a usage error"

# Usage and input errors.
"$hullpack" collision >/dev/null 2>&1; [ $? -eq 64 ] || fail "no arguments: not 64"
"$hullpack" collision "$input" -o "$work/y" --format usd >/dev/null 2>&1; [ $? -eq 64 ] || fail "--format usd: not 64"
"$hullpack" collision "$work/missing.obj" -o "$work/z" 2>"$work/err.log"; [ $? -eq 1 ] || fail "missing input: not 1"
grep -q "missing.obj" "$work/err.log" || fail "the error does not name the file"
"$hullpack" collision --help | grep -q -- "--format" || fail "--help"

[ $failures -eq 0 ] && echo "collision_cli_test: all checks passed"
exit $((failures > 0))
