#!/usr/bin/env bash
# End-to-end checks of `hullpack info`: good files describe themselves, bad ones give one line on
# stderr that names the file and the problem, a non-zero exit, and no crash.
# usage: info_cli_test.sh HULLPACK_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0

check() {  # check NAME EXPECTED_EXIT STDERR_PATTERN -- command...
  local name=$1 want=$2 pattern=$3
  shift 4
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  if [ "$rc" -ge 128 ]; then
    echo "FAIL $name: crashed (exit $rc)"; failures=$((failures + 1)); return
  fi
  if [ "$want" = 0 ] && [ "$rc" -ne 0 ]; then
    echo "FAIL $name: exit $rc: $(cat "$tmp/err")"; failures=$((failures + 1)); return
  fi
  if [ "$want" != 0 ] && [ "$rc" -eq 0 ]; then
    echo "FAIL $name: exit 0, expected an error"; failures=$((failures + 1)); return
  fi
  if [ -n "$pattern" ] && ! grep -q -- "$pattern" "$tmp/err" "$tmp/out"; then
    echo "FAIL $name: output lacks '$pattern': $(head -c 300 "$tmp/err")"; failures=$((failures + 1)); return
  fi
  if [ "$want" != 0 ] && [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
    echo "FAIL $name: expected a one-line error, got: $(cat "$tmp/err")"; failures=$((failures + 1)); return
  fi
  passes=$((passes + 1))
}

check sample 0 "closed, manifold, 1 component, genus 1" -- "$bin" info "$src/samples/torus.obj"
check sample-json 0 '"genus": 1' -- "$bin" info --json "$src/samples/torus.obj"
check no-args 64 "usage" -- "$bin" info
# Packed files list their collision hulls, in the current form and the earlier release's.
"$bin" pack "$src/samples/torus.obj" -o "$tmp/torus.glb" --quiet
check packed-hulls 0 "collision hulls [1-9][0-9]* (convex colliders)" -- "$bin" info "$tmp/torus.glb"
check packed-hulls-json 0 '"collision_hulls": [1-9]' -- "$bin" info --json "$tmp/torus.glb"
# ... and the format versions of their streams (which decoders read the file).
check packed-stream-versions 0 "compressed streams 1 (format 1.1: 1)" -- "$bin" info "$tmp/torus.glb"
"$bin" pack "$src/samples/scans/thorvaldsen_maria.glb" -o "$tmp/maria.glb" --hulls none --max-compression --quiet
check packed-stream-versions-13 0 '"1.3": 1' -- "$bin" info --json "$tmp/maria.glb"
# The physics extensions it reads the hulls from are not listed as ignored.
"$bin" info "$tmp/torus.glb" >"$tmp/info.txt" 2>&1
if grep -q "OMI_physics" "$tmp/info.txt"; then
  echo "FAIL packed-hulls-extensions: $(grep OMI_physics "$tmp/info.txt")"; failures=$((failures + 1))
else
  passes=$((passes + 1))
fi
check pre-1.0-streams-refused 1 "HULLPACK_mesh_compression: stream: bad_version" -- \
  "$bin" info "$src/tests/tools/packed/vectors/cup_hulls_in_stream_omi.glb"
check missing 1 "$tmp/missing.obj: No such file" -- "$bin" info "$tmp/missing.obj"
touch "$tmp/model.xyz"
check unknown-format 1 "$tmp/model.xyz: unknown format '.xyz'" -- "$bin" info "$tmp/model.xyz"
for ext in obj off wrl ply stl gltf glb fbx dae; do
  head -c 3000 /dev/urandom >"$tmp/random.$ext"
  check "random-$ext" 1 "$tmp/random.$ext" -- "$bin" info "$tmp/random.$ext"
  : >"$tmp/empty.$ext"
  check "empty-$ext" 1 "$tmp/empty.$ext" -- "$bin" info "$tmp/empty.$ext"
done
head -c 30000 "$src/samples/torus.obj" >"$tmp/truncated.obj"
check truncated-obj-mid-line 1 "$tmp/truncated.obj: line" -- "$bin" info "$tmp/truncated.obj"
head -n 100 "$src/samples/torus.obj" >"$tmp/truncated2.obj"
check truncated-obj-no-faces 1 "$tmp/truncated2.obj: contains no triangles" -- "$bin" info "$tmp/truncated2.obj"
printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >"$tmp/nan.obj"
check nan 1 "$tmp/nan.obj" -- "$bin" info "$tmp/nan.obj"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' >"$tmp/index.off"
check out-of-range 1 "refers to vertex 7" -- "$bin" info "$tmp/index.off"
mkdir "$tmp/folder.obj"
check dir 1 "$tmp/folder.obj: is a directory" -- "$bin" info "$tmp/folder.obj"

# A COLLADA scene (read through assimp) with a camera and a spot light: both kept, the camera's
# 49.13-degree horizontal view at 16:9 as glTF's vertical 0.5034 rad.
cat >"$tmp/lit.dae" <<'DAE'
<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_cameras><camera id="cam-camera" name="cam"><optics><technique_common><perspective>
    <xfov>49.13434</xfov><aspect_ratio>1.777778</aspect_ratio><znear>0.1</znear><zfar>100</zfar>
  </perspective></technique_common></optics></camera></library_cameras>
  <library_lights><light id="spot-light" name="spot"><technique_common><spot>
    <color>2 2 1</color><falloff_angle>60</falloff_angle>
  </spot></technique_common></light></library_lights>
  <library_geometries><geometry id="tri-mesh" name="tri"><mesh>
    <source id="tri-pos"><float_array id="tri-pos-array" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#tri-pos-array" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#tri-vtx" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene" name="scene">
    <node id="tri" name="tri"><instance_geometry url="#tri-mesh"/></node>
    <node id="cam" name="cam"><translate>0 0 5</translate><instance_camera url="#cam-camera"/></node>
    <node id="spot" name="spot"><translate>0 3 0</translate><instance_light url="#spot-light"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
DAE
check collada-camera-light 0 "cameras 1, lights 1" -- "$bin" info "$tmp/lit.dae"
"$bin" pack "$tmp/lit.dae" -o "$tmp/lit.glb" --hulls none --quiet >/dev/null 2>&1
if grep -a -q '"yfov":0.5033' "$tmp/lit.glb" && grep -a -q '"type":"spot"' "$tmp/lit.glb"; then
  passes=$((passes + 1))
else
  echo "FAIL collada-camera-light: the packed file lacks the camera or the spot light"
  failures=$((failures + 1))
fi

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
