#!/usr/bin/env bash
# inacio2010 Fig. 8 analogue: the ray-cast fluid with the opaque surface transfer function
# beside the translucent one (lower surface opacity). volume_raycast.sh renders both on
# the dam break (its bar: volume_raycast_dam_own_{surface,translucent}.png, both modes'
# metrics against `reference` in volume_raycast_bar.csv); this script sets them side by
# side and measures how far the two images differ (idiff: mean, RMS and largest error,
# PSNR, the share of pixels differing by more than 0.05).
# Writes results/inacio2010/fig8.csv and fig8_pair.png (surface, translucent).
# FS_QUICK=1 (experiments/lib.sh): volume_raycast.sh's quick outputs, in out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, frames_mosaic, study_commit
R=$RESULTS/inacio2010
surface=$R/volume_raycast_dam_own_surface.png translucent=$R/volume_raycast_dam_own_translucent.png
for f in "$surface" "$translucent" "$R/volume_raycast_bar.csv"; do
  [ -f "$f" ] || { echo "fig8.sh: $f missing: run experiments/inacio2010/volume_raycast.sh first" >&2; exit 2; }
done
TMP=out/$(quick "" quick/)inacio2010/fig8
mkdir -p "$TMP"
idiff -a -fail 0.05 "$surface" "$translucent" > "$TMP/idiff.txt" 2>&1 || true # exits 1 on any difference
# idiff prints no statistics for identical images: then every error is 0 (PSNR inf)
stat() { local v; v=$(sed -n "s/^ *$1 *= *\([-0-9.e+]*\).*/\1/p" "$TMP/idiff.txt" | head -1); echo "${v:-$2}"; }
over=$(sed -n 's/^ *[0-9]* pixels (\([0-9.]*\)%) over 0.05.*/\1/p' "$TMP/idiff.txt" | head -1)
{
  echo "# $(csv_commit "$R/volume_raycast_bar.csv"); images and metrics from volume_raycast.sh ($(sed -n '1s/^# *//p' "$R/volume_raycast_bar.csv" | cut -c1-200))"
  echo "row,mask_iou,normal_mean_deg,interior_normal_mean_deg,image_mean_error,image_rms_error,image_max_error,image_psnr_db,image_pixels_over_0.05_pct"
  csv_awk 'if (col("method") == "volume_raycast") { m = col("variant"); sub(/.*mode=/, "", m)
    print m " against reference," col("mask_iou") "," col("normal_mean_deg") "," col("interior_normal_mean_deg") ",,,,," }' \
    "$R/volume_raycast_bar.csv"
  echo "translucent image against surface image,,,,$(stat "Mean error" 0),$(stat "RMS error" 0),$(stat "Max error" 0),$(stat "Peak SNR" inf),${over:-0}"
} > "$R/fig8.csv"
frames_mosaic "$R/fig8_pair.png" 2x1 "$(quick 400x400 64x64)" "$surface" "$translucent"
echo "wrote $R/fig8.csv, $R/fig8_pair.png"
