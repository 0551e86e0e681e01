#!/usr/bin/env bash
# The camera and frames of render and compare from the command line: --camera-from another
# render's EXR gives an image diff compares with it (the same pixels); render --save-scene
# writes a scene file that renders the same image and saves back to the same bytes; the
# auto-framed camera does not move when r is 3% off; --camera places it, its up the scene's
# up axis unless given; frame patterns (%04d, {}) with --frame and --frames A:B:STEP in
# render and compare; compare names the up axis before it renders; info prints the guess.
# Each refusal is one line, exit 2, nothing written. usage: tests/cli_camera.sh BIN SRC OUT
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
attr() { iinfo -v "$1" 2>/dev/null | sed -n "s/^ *fluidsurf:$2: \"\(.*\)\"$/\1/p"; }
render() { "$BIN" render "$@" --method reference -q; }
D=$SRC/experiments/data/splashsurf
cube=$D/cube_2366_particles.vtk
column=$D/hilbert2_7954_particles.vtk # stands on z = 0: auto gives z

# --camera-from: the same camera, so the same image
render "$cube" -W 40 -H 30 -o "$T/a.exr"; render "$cube" --camera-from "$T/a.exr" -o "$T/b.exr"
"$BIN" diff "$T/a.exr" "$T/b.exr" --strict --fail-iou 1 --fail-depth-r 0 --fail-normal-deg 0 > "$T/ab.txt" 2>&1
check '[ $? = 0 ] && [ "$(attr "$T/a.exr" camera)" = "$(attr "$T/b.exr" camera)" ]' \
  "--camera-from a.exr renders a.exr's camera and size: diff --strict finds no difference ($(tail -c 300 "$T/ab.txt"))"
# r 3% off: the auto-framed camera stays, so diff compares the two
render "$cube" -W 40 -H 30 --radius 0.025 -o "$T/r1.exr"; render "$cube" -W 40 -H 30 --radius 0.02575 -o "$T/r2.exr"
"$BIN" diff "$T/r1.exr" "$T/r2.exr" > "$T/r12.txt" 2>&1; rc=$?
check '[ "$(attr "$T/r1.exr" camera)" = "$(attr "$T/r2.exr" camera)" ] && [ $rc != 2 ]' \
  "--radius 3% off frames the same camera ($(attr "$T/r1.exr" camera) vs $(attr "$T/r2.exr" camera))"

# --save-scene: the scene file renders the same image, and saves back to the same bytes
render "$column" -W 40 -H 30 --set reference.supersample=2 --save-scene "$T/s1.json" -o "$T/c.exr"
render "$T/s1.json" --save-scene "$T/s2.json" -o "$T/d.exr"
"$BIN" diff "$T/c.exr" "$T/d.exr" --fail-iou 1 --fail-depth-r 0 --fail-normal-deg 0 > "$T/cd.txt" 2>&1
check '[ $? = 0 ] && cmp -s "$T/s1.json" "$T/s2.json"' \
  "--save-scene: the scene renders the same image, and saves to the same bytes ($(tail -c 300 "$T/cd.txt"))"
check 'grep -q "\"up\":.*\"z\"" "$T/s1.json" && grep -q "\"supersample\":.*2" "$T/s1.json"' \
  "the saved scene holds the settled up axis and the --set ($(tr -d '\n\t' < "$T/s1.json" | head -c 300))"

# --camera: up follows the scene's up axis unless given
render "$column" -W 16 -H 16 --camera 'eye=3,2,1;target=0,0,0.5' -o "$T/e.exr"
check '[ "$(attr "$T/e.exr" camera | sed "s/.*;up=\([^;]*\);.*/\1/")" = 0,0,1 ]' "--camera without up: the scene's up, z ($(attr "$T/e.exr" camera))"
render "$column" --camera 'eye=3,2,1;target=0,0,0.5;up=x;fov=30;size=20x10' -o "$T/f.exr"
check 'attr "$T/f.exr" camera | grep -q "^eye=3,2,1;target=0,0,0.5;up=1,0,0;fov=30;size=20x10$"' \
  "--camera with up=x, fov and size: as given ($(attr "$T/f.exr" camera))"

# refusals: one line, exit 2, no output
refused() { # what output command...
  local what=$1 out=$2; shift 2
  "$@" 2> "$T/err"; local rc=$?
  check '[ $rc = 2 ] && [ "$(wc -l < "$T/err")" = 1 ] && [ ! -e "$out" ]' "$what is refused: exit $rc, $(head -c 200 "$T/err")"
}
refused "a camera without target" "$T/x.png" render "$cube" --camera 'eye=1,2,3' -o "$T/x.png"
refused "a camera with a bad key" "$T/x.png" render "$cube" --camera 'eye=1,2,3;target=0,0,0;zoom=2' -o "$T/x.png"
refused "eye = target" "$T/x.png" render "$cube" --camera 'eye=1,2,3;target=1,2,3' -o "$T/x.png"
refused "--camera with --camera-from" "$T/x.png" render "$cube" --camera 'eye=1,2,3;target=0,0,0' --camera-from "$T/a.exr" -o "$T/x.png"
refused "--camera-from a file without a camera" "$T/x.png" render "$cube" --camera-from "$T/s1.json" -o "$T/x.png"
refused "--camera-from a missing file" "$T/x.png" render "$cube" --camera-from "$T/none.exr" -o "$T/x.png"
refused "--save-scene not .json" "$T/x.png" render "$cube" --save-scene "$T/s.txt" -o "$T/x.png"
refused "compare --camera without eye" "$T/cmpx" "$BIN" compare "$cube" --camera 'target=0,0,0' -o "$T/cmpx"

# frame patterns: %04d with --frame, {} with --frames A:B:STEP, in render and compare
for f in 1 2 3 4 5; do ln -s "$cube" "$T/f_000$f.vtk"; done
render "$T/f_%04d.vtk" --frame 2 -W 16 -H 16 -o "$T/one.png"
check '[ $? = 0 ] && [ -s "$T/one.png" ]' "render 'f_%04d.vtk' --frame 2"
render "$T/f_000{}.vtk" --frames 1:5:2 -W 16 -H 16 -o "$T/seq_{}.exr"
check '[ $? = 0 ] && [ -s "$T/seq_1.exr" ] && [ -s "$T/seq_3.exr" ] && [ -s "$T/seq_5.exr" ] && [ ! -e "$T/seq_2.exr" ]' \
  "render 'f_000{}.vtk' --frames 1:5:2: frames 1, 3, 5 ($(ls "$T" | grep seq_ | tr '\n' ' '))"
refused "a pattern without --frames" "$T/y.png" render "$T/f_%04d.vtk" -W 16 -H 16 -o "$T/y.png"
refused "several frames into one file" "$T/y.png" render "$T/f_%04d.vtk" --frames 1:2 -W 16 -H 16 -o "$T/y.png"
refused "a bad --frames" "$T/y_{}.png" render "$T/f_%04d.vtk" --frames 3:1 -W 16 -H 16 -o "$T/y_{}.png"
"$BIN" compare "$T/f_000{}.vtk" --frames 1:5:2 --methods spheres -W 16 -H 16 --repeat 1 --no-cache -o "$T/cmp" 2> "$T/cmp.err"
check '[ $? = 0 ] && [ "$(grep -c "^spheres,.*,reference" "$T/cmp/metrics.csv")" = 3 ] && grep -q "^3,\|,3," "$T/cmp/temporal.csv"' \
  "compare 'f_000{}.vtk' --frames 1:5:2: three frames ($(head -c 300 "$T/cmp.err"))"
check '[ "$(grep -n "up is y" "$T/cmp.err" | cut -d: -f1)" -lt "$(grep -n "work items" "$T/cmp.err" | head -1 | cut -d: -f1)" ] 2> /dev/null' \
  "compare names the up axis before it renders ($(head -3 "$T/cmp.err" | tr '\n' '|'))"

"$BIN" info "$column" > "$T/info.txt"
check 'grep -q "^up (auto): z (a floor at 0: " "$T/info.txt" && grep -q "^within r of the low end: x .*%, y .*%, z .*%$" "$T/info.txt"' \
  "info prints the up guess, its reason and the shares ($(grep -A1 "^up" "$T/info.txt" | tr '\n' '|'))"

echo "cli_camera: $fails failure(s)"
[ "$fails" = 0 ]
