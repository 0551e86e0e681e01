#!/usr/bin/env bash
# xu2022 Fig. 2 analogue: isotropic against anisotropic sprites with no filter, the
# comparison the paper draws before any smoothing. The images are fig6.sh's "none"
# column (run it first): the jittered box against `analytic` and the dam break against
# `reference`, 512^2, shipped defaults otherwise.
# Writes results/xu2022/fig2_pair.png (rows box, dam break; columns the ground truth,
# isotropic, anisotropic) and fig2.csv (the unfiltered variants' coverage and normal
# error, from fig6.sh's metrics). FS_QUICK=1: fig6.sh's quick outputs, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, study_commit, frames_mosaic
OUT=$RESULTS/xu2022
D=out/$(quick "" quick/)xu2022/fig6
mkdir -p "$OUT"
imgs=()
for spec in box:analytic dam:reference; do
  IFS=: read -r scene ref <<< "$spec"
  for f in "$D/$scene/$ref.png" "$D/$scene/aniso_ssf_anisotropy-off_filter-none.png" \
           "$D/$scene/aniso_ssf_anisotropy-on_filter-none.png" "$D/$scene/metrics.csv"; do
    [ -f "$f" ] || { echo "fig2.sh: $f missing: run experiments/xu2022/fig6.sh first" >&2; exit 2; }
  done
  imgs+=("$D/$scene/$ref.png" "$D/$scene/aniso_ssf_anisotropy-off_filter-none.png" "$D/$scene/aniso_ssf_anisotropy-on_filter-none.png")
done
{
  echo "# $(csv_commit "$D/box/metrics.csv" "$D/dam/metrics.csv"); from fig6.sh's metrics ($D/{box,dam}/metrics.csv), filter none"
  echo "scene,reference,anisotropy,mask_iou,normal_mean_deg,interior_normal_mean_deg,depth_rmse_r"
  for spec in box:analytic dam:reference; do
    IFS=: read -r scene ref <<< "$spec"
    csv_awk -v s="$scene" -v r="$ref" 'if (col("method") == "aniso_ssf" && col("variant") ~ /filter=none$/ && col("reference") == r) {
      a = col("variant"); sub(/;.*/, "", a); sub(/anisotropy=/, "", a)
      print s "," r "," a "," col("mask_iou") "," col("normal_mean_deg") "," col("interior_normal_mean_deg") "," col("depth_rmse_r") }' "$D/$scene/metrics.csv"
  done
} > "$OUT/fig2.csv.tmp"
publish "$OUT/fig2.csv"
frames_mosaic "$OUT/fig2_pair.png" 3x2 "$(quick 300x300 64x64)" "${imgs[@]}"
echo "wrote $OUT/fig2.csv, $OUT/fig2_pair.png"
