#!/usr/bin/env bash
# iwasaki2006 Fig. 8 analogue: the surface from the slice-splatted density grid (the
# paper's GPU path, surfels.grid_build=splat) beside the one from the exact CPU sum
# (grid_build=exact), both rendered by surfels at its defaults on the dam break at
# SIZE^2 (default 512), each against the exact `reference`, and the splat image
# against the exact-grid image itself (`fluidsurf diff`). density_grid.sh measures the
# grids themselves and their build times.
# Writes results/iwasaki2006/fig8.csv (rows: splat and exact against the reference,
# splat against exact) and fig8_pair.png (splat, exact; the surfels' own appearance).
# Work in out/iwasaki2006/fig8/. FS_QUICK=1 (experiments/lib.sh): 128^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
OUT=$RESULTS/iwasaki2006
TMP=out/$(quick "" quick/)iwasaki2006/fig8
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "fig8.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
"$BIN" compare --force --no-cache experiments/scenes/dam_break.json --methods surfels --set surfels.grid_build=splat,exact \
    --reference reference -W "$SIZE" -H "$SIZE" --repeat 1 -o "$TMP" -q 2> "$TMP/compare.log"
splat=$TMP/surfels_grid_build-splat.exr exact=$TMP/surfels_grid_build-exact.exr
"$BIN" diff "$splat" "$exact" > "$TMP/diff.txt"
# diff prints "name value" lines, named as metrics.csv's columns
val() { awk -v k="$1" '$1 == k { print $2 }' "$TMP/diff.txt"; }
{
  sed -n 1p "$TMP/metrics.csv" | cut -c1-600
  echo "image,against,mask_iou,depth_rmse_r,normal_mean_deg,interior_normal_mean_deg,psnr_db,ssim"
  csv_awk 'if (col("method") == "surfels") { g = col("variant"); sub(/.*grid_build=/, "", g)
    print g ",reference," col("mask_iou") "," col("depth_rmse_r") "," col("normal_mean_deg") "," col("interior_normal_mean_deg") "," col("psnr_db") "," col("ssim") }' "$TMP/metrics.csv"
  echo "splat,exact,$(val mask_iou),$(val depth_rmse_r),$(val normal_mean_deg),$(val interior_normal_mean_deg),$(val psnr_db),$(val ssim)"
} > "$OUT/fig8.csv"
stamp_csv "$OUT/fig8.csv"
frames_mosaic "$OUT/fig8_pair.png" 2x1 "$(quick 400x400 64x64)" "$TMP/surfels_grid_build-splat_own.png" \
  "$TMP/surfels_grid_build-exact_own.png"
echo "wrote $OUT/fig8.csv, $OUT/fig8_pair.png"
