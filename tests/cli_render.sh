#!/usr/bin/env bash
# The render CLI end to end: PNG and EXR outputs exist, the EXR carries the
# G-buffer channels and the provenance, --timings names the renderer.
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
# every check below is one "cond || fail" line; count them for the summary
n=$(($(grep -c '|| fail' "$0") - 1)) # minus this line
cube=$SRC/experiments/data/splashsurf/cube_2366_particles.vtk
"$BIN" render "$cube" --method spheres -W 96 -H 64 -q --timings -o "$T/cube.exr" > "$T/timings.csv" || fail "spheres exr render"
# the splat stage is GL work: a wall time, a GL-clock time (GL_TIMESTAMP, core since GL 3.3)
# and the GL renderer's name, not CPU and not empty (the EXR's gl_renderer, checked below)
splat_renderer=$(awk -F, '$1 == "splat" && $2 ~ /^[0-9]+\.[0-9]+$/ && $3 ~ /^[0-9]+\.[0-9]+$/ && $4 != "" && $4 != "CPU" {
  sub(/^[^,]*,[^,]*,[^,]*,/, ""); print; n++ } END { exit n != 1 }' "$T/timings.csv") || fail "timings lack one splat row with ms, gpu_ms and a GL renderer: $(cat "$T/timings.csv")"
grep -q '^load,.*,CPU$' "$T/timings.csv" || fail "load stage not marked CPU"
# spheres reads no neighbour grid (FS_GRID_UNUSED), so none is built; a method that reads one times it on the CPU
! grep -q '^grid,' "$T/timings.csv" || fail "spheres built a grid nobody reads"
"$BIN" render "$cube" --method reference -W 24 -H 16 -q --timings -o "$T/cube_ref.png" > "$T/timings_ref.csv" || fail "reference render"
grep -q '^grid,.*,CPU$' "$T/timings_ref.csv" || fail "grid stage not marked CPU"
if command -v iinfo >/dev/null; then
  iinfo -v "$T/cube.exr" > "$T/iinfo.txt" 2>&1
  for ch in depth normal.X normal.Y normal.Z thickness coverage; do grep -q "$ch" "$T/iinfo.txt" || fail "EXR lacks channel $ch"; done
  for a in fluidsurf:commit fluidsurf:gl_renderer fluidsurf:camera fluidsurf:params fluidsurf:scene_hash; do
    grep -q "$a" "$T/iinfo.txt" || fail "EXR lacks attribute $a"; done
  grep -qF "fluidsurf:gl_renderer: \"$splat_renderer\"" "$T/iinfo.txt" || fail "--timings names renderer '$splat_renderer', the EXR: $(grep gl_renderer "$T/iinfo.txt")"
  grep -q "96 x  *64" "$T/iinfo.txt" || fail "EXR size is not 96x64: $(head -3 "$T/iinfo.txt")"
else
  fail "iinfo (openimageio-tools) missing"
fi
"$BIN" render "$cube" --method reference -W 64 -H 64 -q -o "$T/cube.png" || fail "reference png render"
[ -s "$T/cube.png" ] || fail "no PNG written"
"$BIN" methods | grep -q '^reference' || fail "methods does not list reference"
"$BIN" methods | grep -q 'step_min' || fail "methods does not list parameters"
"$BIN" info "$cube" | grep -q 'particles: 2366' || fail "info count"
"$BIN" convert "$cube" -o "$T/cube.ply" && "$BIN" info "$T/cube.ply" | grep -q 'particles: 2366' || fail "convert to ply"
# every point array is listed and converted (issue 53: DualSPHysics' Idp and Rhop were dropped)
crop=$SRC/experiments/data/dualsphysics/dambreak200k_t0.300_crop902.vtk
"$BIN" info "$crop" | grep -qx 'point arrays: Idp (1 x uint32), Rhop (1 x float32)' || fail "info lists Idp and Rhop: $("$BIN" info "$crop" 2>&1 | grep -i array)"
for e in ply bgeo vtk; do
  "$BIN" convert "$crop" -o "$T/crop.$e" && "$BIN" info "$T/crop.$e" | grep -qx 'point arrays: Idp (1 x u*int32), Rhop (1 x float32)' || fail "convert to .$e keeps Idp and Rhop: $("$BIN" info "$T/crop.$e" 2>&1 | grep -i array)"
done
"$BIN" convert "$crop" -o "$T/crop.vdb" 2> "$T/vdb.err" && grep -q "keeps no point arrays: 2 of" "$T/vdb.err" || fail "convert to .vdb says what it drops: $(cat "$T/vdb.err")"
# most particles on one point (a simulator's clamp piles them up): no spacing to measure,
# an error only when nothing else gives a radius
{ echo x,y,z; for i in $(seq 50); do echo 0.5,0.5,0.5; done; for i in $(seq 10); do echo "0.$i,0,0"; done; } > "$T/piled.csv"
"$BIN" info "$T/piled.csv" > /dev/null 2> "$T/piled.err" && fail "info without a radius on piled particles succeeded"
grep -q 'no spacing to estimate a radius' "$T/piled.err" || fail "info on piled particles: $(cat "$T/piled.err")"
"$BIN" info "$T/piled.csv" --radius 0.02 | grep -q 'radius r: 0.02 (--radius)' || fail "info --radius on piled particles"
# a scene file converts too: its synthetic frame, with the scene's r
printf '{"particles": {"synthetic": "box", "size": [4, 5, 6], "seed": 3}, "radius": 0.01}' > "$T/box120.json"
"$BIN" convert "$T/box120.json" -o "$T/box120.ply" && "$BIN" info "$T/box120.ply" | grep -q 'particles: 120' || fail "convert a synthetic scene"
grep -aq 'comment radius 0.0099999' "$T/box120.ply" || fail "convert a scene: r not written"
# a frame sequence: a printf pattern with first/last, one frame picked by --frame
mkdir -p "$T/seq"
cp "$SRC/experiments/data/splashsurf/double_dam_break_frame_01_4732_particles.vtk" "$T/seq/frame_0001.vtk"
cp "$SRC/experiments/data/splashsurf/double_dam_break_frame_26_4732_particles.vtk" "$T/seq/frame_0002.vtk"
printf '{"particles": {"file": "seq/frame_%%04d.vtk", "first": 1, "last": 2}, "camera": {"width": 48, "height": 48}}' > "$T/seq.json"
"$BIN" render "$T/seq.json" --method spheres --frame 2 -q -o "$T/seq2.exr" || fail "render frame 2 of a pattern"
"$BIN" render "$T/seq.json" --method spheres -q -o "$T/seq1.exr" || fail "render the first frame of a pattern"
iinfo -v "$T/seq2.exr" 2>/dev/null | grep -q 'fluidsurf:frame: "2"' || fail "frame 2 not recorded in the provenance"
! cmp -s "$T/seq1.exr" "$T/seq2.exr" || fail "frames 1 and 2 rendered identically"
"$BIN" render "$T/seq.json" --method spheres --frame 3 -q -o "$T/seq3.exr" 2>/dev/null; [ $? -eq 2 ] || fail "a missing frame is not exit 2"
# per-particle colour reaches the G-buffer of a method that tracks it (raycast_pca), not of one that does not
awk 'BEGIN { print "x,y,z,r,g,b"; for (i = 0; i < 12; i++) for (j = 0; j < 6; j++) for (k = 0; k < 6; k++)
  printf "%g,%g,%g,%d,0,%d\n", i * 0.05, j * 0.05, k * 0.05, (i < 6), (i >= 6) }' > "$T/two_blocks.csv"
"$BIN" render "$T/two_blocks.csv" --method raycast_pca --radius 0.025 -W 48 -H 48 -q -o "$T/colour.exr" || fail "render coloured particles"
iinfo -v "$T/colour.exr" 2>/dev/null | grep -q "color.R" || fail "coloured particles: no colour layer in the EXR"
"$BIN" render "$T/two_blocks.csv" --method spheres --radius 0.025 -W 48 -H 48 -q -o "$T/nocolour.exr" || fail "render coloured particles with spheres"
! iinfo -v "$T/nocolour.exr" 2>/dev/null | grep -q "color.R" || fail "spheres does not track colour, yet the EXR has a colour layer"
for c in render info convert methods; do "$BIN" $c --help | grep -q usage || fail "$c --help"; done
echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
