#!/usr/bin/env bash
# xiao2017 Fig. 4 analogue: breaking two fluid cubes, 100k particles, rendered with
# raycast_pca at four moments, as the paper's four panels: the cubes at rest (sharp
# corners), two moments of splash and thin sheets, the settling pool. The sequence is
# fluidsurf's own SPH (`simulate double_dam_break`, deterministic); each chosen frame
# is compared against the exact `reference`, with `spheres` as the floor, under one
# camera (auto-framed on the first frame, which spans the tank).
# Writes results/xiao2017/fig4.csv (per frame and method: coverage, normal and depth
# error, frame time on the renderer named in its provenance), fig4_raycast_pca.png and
# fig4_reference.png (the four frames, 2 x 2). Work in out/xiao2017/fig4/.
# FS_QUICK=1 (experiments/lib.sh): 5k particles, 128^2, into out/quick/results/xiao2017.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, auto_camera, simulated_frames, frame_scene, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
N=${N:-$(quick 100000 5000)}
FRAMES=${FRAMES:-$(quick "0 30 60 120" "0 3 6 9")} # at 60 fps: t = 0, 0.5, 1 and 2 s
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/fig4
mkdir -p "$OUT" "$TMP/sim"
[ -x "$BIN" ] || { echo "fig4.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
last=$(tr ' ' '\n' <<< "$FRAMES" | sort -n | tail -1)
pat=$TMP/sim/frame_%04d.bgeo
simulated_frames "$BIN" double_dam_break "$N" "$last" "$pat"
first=${FRAMES%% *}
frame_scene "$pat" "$first" "$SIZE" > "$TMP/frame_first.json"
auto_camera "$BIN" "$TMP/frame_first.json" "$TMP"
# the automatic framing fits a quantile box of the particles, which trims the outer
# faces of two cubes far apart: widen the view so the whole tank is in it
P_CAMERA=${P_CAMERA/\"fov\": $FOV/\"fov\": $(awk -v f="$FOV" 'BEGIN {print f * 1.3}')}
{
  printf '# %s; particles=%s; sequence=simulate double_dam_break at 60 fps\n' "$(study_commit)" "$N"
  echo "frame,t_s,method,mask_iou,normal_mean_deg,interior_normal_mean_deg,depth_rmse_r,frame_ms"
} > "$TMP/fig4.csv"
for f in $FRAMES; do
  frame_scene "$pat" "$f" "$SIZE" "$P_CAMERA" > "$TMP/frame_$f.json"
  d=$TMP/frame_$f
  "$BIN" compare --force --no-cache "$TMP/frame_$f.json" --methods raycast_pca,spheres --reference reference \
      --repeat "$(quick 3 1)" -o "$d" -q 2> "$d.log"
  [ "$f" = "$first" ] && sed -n '1s/^# *\(.*\)$/# compare: \1/p' "$d/metrics.csv" >> "$TMP/fig4.csv.prov"
  awk -F, -v f="$f" '$1 == "raycast_pca" || $1 == "spheres" {
      printf "%s,%.3f,%s,%s,%s,%s,%s,%s\n", f, f / 60, $1, $5, $9, $11, $7, $14 }' "$d/metrics.csv" >> "$TMP/fig4.csv"
  echo "fig4: frame $f done"
done
{ sed -n 1p "$TMP/fig4.csv"; cut -c1-600 "$TMP/fig4.csv.prov"; sed 1d "$TMP/fig4.csv"; } > "$OUT/fig4.csv"
rm -f "$TMP/fig4.csv.prov"
for m in raycast_pca reference; do
  frames_mosaic "$OUT/fig4_$m.png" 2x2 "$(quick 400x400 64x64)" $(for f in $FRAMES; do echo "$TMP/frame_$f/$m.png"; done)
done
echo "wrote $OUT/fig4.csv, $OUT/fig4_raycast_pca.png, $OUT/fig4_reference.png"
