#!/usr/bin/env bash
# inacio2010 Fig. 8 analogue: the ray-cast fluid with the opaque surface transfer function
# beside the translucent one (lower surface opacity), volume_raycast at its defaults on
# the dam break at SIZE^2 (default 512), its own appearance; and how far the two images
# differ (idiff: mean, RMS and largest error, PSNR, the share of pixels differing by more
# than 0.05). The G-buffer metrics of both modes against `reference` go to fig8.csv too.
# Writes results/inacio2010/fig8.csv, fig8_pair.png (surface, translucent).
# Work in out/inacio2010/fig8/. FS_QUICK=1 (experiments/lib.sh): 128^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, frames_mosaic, study_commit
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
OUT=$RESULTS/inacio2010
TMP=out/$(quick "" quick/)inacio2010/fig8
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "fig8.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
"$BIN" compare --no-cache experiments/scenes/dam_break.json --methods volume_raycast \
    --set volume_raycast.mode=surface,translucent --reference reference -W "$SIZE" -H "$SIZE" --repeat 1 \
    -o "$TMP" -q 2> "$TMP/compare.log"
surface=$TMP/volume_raycast_mode=surface_own.png translucent=$TMP/volume_raycast_mode=translucent_own.png
idiff -a -fail 0.05 "$surface" "$translucent" > "$TMP/idiff.txt" 2>&1 || true # exits 1 on any difference
stat() { sed -n "s/^ *$1 *= *\([-0-9.e+]*\).*/\1/p" "$TMP/idiff.txt" | head -1; }
over=$(sed -n 's/^ *[0-9]* pixels (\([0-9.]*\)%) over 0.05.*/\1/p' "$TMP/idiff.txt" | head -1)
{
  sed -n 1p "$TMP/metrics.csv" | cut -c1-600
  echo "row,mask_iou,normal_mean_deg,interior_normal_mean_deg,image_mean_error,image_rms_error,image_max_error,image_psnr_db,image_pixels_over_0.05_pct"
  awk -F, '$1 == "volume_raycast" { m = $2; sub(/.*mode=/, "", m); print m " against reference," $5 "," $9 "," $11 ",,,,," }' \
    "$TMP/metrics.csv"
  echo "translucent image against surface image,,,,$(stat "Mean error"),$(stat "RMS error"),$(stat "Max error"),$(stat "Peak SNR"),${over:-0}"
} > "$OUT/fig8.csv"
frames_mosaic "$OUT/fig8_pair.png" 2x1 "$(quick 400x400 64x64)" "$surface" "$translucent"
echo "wrote $OUT/fig8.csv, $OUT/fig8_pair.png"
