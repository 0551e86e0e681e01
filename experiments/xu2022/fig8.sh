#!/usr/bin/env bash
# xu2022 Fig. 8 analogue: the four filters (gaussian, bilateral, curvature flow,
# narrow-range; anisotropy on, shipped defaults) on a transparent fluid. The dam
# break under the scene's water material (Fresnel reflection, refraction through
# the thickness, absorption: common/eval/shading.c) at 512^2 (fig6.sh's) against
# the exact `reference`. Besides the G-buffer metrics, experiments/tools/highlights
# measures the paper's second claim, that narrow-range's highlight "forms an obvious
# bright area": how much of each image's highlight lies in broad areas rather than
# speckle, beside the reference's own.
# Writes results/xu2022/fig8.csv (metrics), fig8_highlights.csv (highlight layout at
# three luminance thresholds) and fig8_row.png (reference, then the four filters,
# cropped and shrunk), from fig6.sh's dam-break outputs in out/xu2022/fig6/dam/ (run it first).
# FS_QUICK=1 (experiments/lib.sh): fig6.sh's quick outputs (128^2), into out/quick/results/xu2022.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, frames_mosaic
TOOL=${TOOL:-./build/experiments/highlights}
SIZE=$(quick 512 128) # fig6.sh's
OUT=$RESULTS/xu2022
mkdir -p "$OUT"
[ -x "$TOOL" ] || { echo "fig8.sh: $TOOL missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
# fig6.sh renders these very images (the dam break, anisotropy on, every filter, against
# `reference`): read its outputs rather than render them twice
D=out/$(quick "" quick/)xu2022/fig6/dam
FILTERS="gaussian bilateral curvature narrow"
exrs=("$D/reference.exr")
for f in $FILTERS; do exrs+=("$D/aniso_ssf_anisotropy-on_filter-$f.exr"); done
for e in "${exrs[@]}" "$D/metrics.csv"; do
  [ -f "$e" ] || { echo "fig8.sh: $e missing: run experiments/xu2022/fig6.sh first" >&2; exit 2; }
done
# fig8.csv: the G-buffer metrics of each filter against the reference
{
  sed -n 1p "$D/metrics.csv"
  echo "filter,interior_normal_mean_deg,normal_p95_deg,depth_rmse_r,psnr_db,ssim"
  csv_awk -v want="$FILTERS" 'if (col("method") == "aniso_ssf" && col("variant") ~ /^anisotropy=on;/ && col("reference") == "reference") {
    f = col("variant"); sub(/.*filter=/, "", f)
    if (index(" " want " ", " " f " "))
      print f "," col("interior_normal_mean_deg") "," col("normal_p95_deg") "," col("depth_rmse_r") "," col("psnr_db") "," col("ssim") }' \
    "$D/metrics.csv"
} > "$OUT/fig8.csv"
# fig8_highlights.csv: the highlight layout of every image, the reference's too, over
# luminance thresholds (below about 0.6 the refracted white squares of the floor count)
{
  echo "# $(csv_commit "$D/metrics.csv") (the images); highlights tool built at ${STUDY_PROV//=/ }; tool=experiments/tools/highlights --min-area 16; images as in fig8.csv"
  echo "image,threshold,highlight_pct,areas,largest_px,share_in_large_pct"
  for t in 0.6 0.7 0.8; do
    "$TOOL" --threshold "$t" --min-area 16 "${exrs[@]}" | awk -F, -v t="$t" -v dir="$D/" 'NR > 1 {
      f = $1; sub(dir, "", f); sub(/\.exr$/, "", f); sub(/^aniso_ssf_anisotropy-on_filter-/, "", f)
      print f "," t "," $4 "," $5 "," $6 "," $7 }'
  done
} > "$OUT/fig8_highlights.csv"
# the row: reference, then the four filters, each cropped to the wave and shrunk
crop=$(awk -v s="$SIZE" 'BEGIN {f = s / 512; printf "%dx%d+%d+%d", 400 * f, 400 * f, 50 * f, 30 * f}')
frames_mosaic "$OUT/fig8_row.png" 5x1 "$(quick 220x220 64x64)" --cut "$crop" $(for e in "${exrs[@]}"; do echo "${e%.exr}.png"; done)
echo "wrote $OUT/fig8.csv, $OUT/fig8_highlights.csv, $OUT/fig8_row.png"
