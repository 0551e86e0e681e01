#!/usr/bin/env bash
# xiao2017 Fig. 6 analogue: four spouts of differently coloured fluid fill a pool and
# mix; raycast_pca tracks the surface colour from the particles (the normals pass
# writes the kernel-weighted particle colour at each hit, methods/raycast_pca/README.md).
# The sequence is fluidsurf's own SPH (`simulate spouts`: 12,000 particles, 35% in the
# pool at rest, four spouts of colours 1 to 4). At three moments (jets, filling, mixed)
# raycast_pca is compared against the exact `reference`; the reference has no colour,
# so the colour is judged in the images only.
# Writes results/xiao2017/fig6.csv, fig6_raycast_pca.png (the three moments, colour
# shading over the checker) and fig6_reference.png. Work in out/xiao2017/fig6/.
# FS_QUICK=1 (experiments/lib.sh): 3,000 particles, 128^2, into out/quick/results/xiao2017.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, auto_camera, simulated_frames, frame_scene, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
N=${N:-$(quick 12000 3000)}
FRAMES=${FRAMES:-$(quick "60 180 360" "6 12 18")} # at 60 fps: t = 1, 3 and 6 s
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/fig6
mkdir -p "$OUT" "$TMP/sim"
[ -x "$BIN" ] || { echo "fig6.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
last=$(tr ' ' '\n' <<< "$FRAMES" | sort -n | tail -1)
pat=$TMP/sim/frame_%04d.bgeo
simulated_frames "$BIN" spouts "$N" "$last" "$pat"
first=${FRAMES%% *}
frame_scene "$pat" "$first" "$SIZE" > "$TMP/frame_first.json"
auto_camera "$BIN" "$TMP/frame_first.json" "$TMP"
{
  printf '# %s; particles=%s; sequence=simulate spouts at 60 fps\n' "$(study_commit)" "$N"
  echo "frame,t_s,particles,mask_iou,normal_mean_deg,interior_normal_mean_deg,frame_ms"
} > "$TMP/fig6.csv"
for f in $FRAMES; do
  frame_scene "$pat" "$f" "$SIZE" "$P_CAMERA" > "$TMP/frame_$f.json"
  d=$TMP/frame_$f
  "$BIN" compare --force --no-cache "$TMP/frame_$f.json" --methods raycast_pca --reference reference \
      --repeat "$(quick 3 1)" -o "$d" -q 2> "$d.log"
  [ "$f" = "$first" ] && sed -n '1s/^# *\(.*\)$/# compare: \1/p' "$d/metrics.csv" | cut -c1-600 > "$TMP/prov"
  n=$("$BIN" info "$(printf "$pat" "$f")" 2> /dev/null | sed -n 's/^particles: //p')
  awk -F, -v f="$f" -v n="$n" '$1 == "raycast_pca" {
      printf "%s,%.3f,%s,%s,%s,%s,%s\n", f, f / 60, n, $5, $9, $11, $14 }' "$d/metrics.csv" >> "$TMP/fig6.csv"
  echo "fig6: frame $f done"
done
{ sed -n 1p "$TMP/fig6.csv"; cat "$TMP/prov"; sed 1d "$TMP/fig6.csv"; } > "$OUT/fig6.csv"
for m in raycast_pca reference; do
  frames_mosaic "$OUT/fig6_$m.png" 3x1 "$(quick 400x400 64x64)" $(for f in $FRAMES; do echo "$TMP/frame_$f/$m.png"; done)
done
echo "wrote $OUT/fig6.csv, $OUT/fig6_raycast_pca.png, $OUT/fig6_reference.png"
