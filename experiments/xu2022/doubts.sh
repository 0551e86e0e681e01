#!/usr/bin/env bash
# The two doubts in methods/aniso_ssf/README.md, measured (shipped defaults otherwise):
#  1. narrow-range depth bias: the jittered slab against `analytic`, seen obliquely
#     (experiments/scenes/slab.json) and from nearly straight above
#     (experiments/xu2022/slab_topdown.json), filters none / gaussian / narrow, anisotropy on;
#     if the bias toward the camera comes from the one-sided range test on sloped depth,
#     it vanishes head-on.
#  2. curvature-flow time step and iteration count: the box against `analytic` with
#     80 (the paper's) and 320 iterations, at 256^2, 512^2 and 1024^2: the step is a
#     fixed diffusion per pixel, so at a higher resolution the same 80 iterations smooth
#     less in world units.
# Writes results/xu2022/doubts_narrow_bias.csv and doubts_curvature.csv.
# FS_QUICK=1 (experiments/lib.sh): 1. at 128^2, 2. at 64^2 and 128^2; into
# out/quick/results/xu2022 and out/quick/xu2022/doubts.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
OUT=$RESULTS/xu2022
TMP=out/$(quick "" quick/)xu2022/doubts
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "doubts.sh: $BIN missing" >&2; exit 2; }
pick() {
  csv_awk -v tag="$1" 'if (col("method") == "aniso_ssf") print tag "," col("variant") "," col("mask_iou") "," col("depth_bias_r") "," col("depth_rmse_r") "," col("interior_normal_mean_deg")' "$2"
}

csv=$OUT/doubts_narrow_bias.csv
echo "view,variant,mask_iou,depth_bias_r,depth_rmse_r,interior_normal_mean_deg" > "$csv.tmp"
for spec in oblique:experiments/scenes/slab.json topdown:experiments/xu2022/slab_topdown.json; do
  IFS=: read -r view scene <<< "$spec"
  "$BIN" compare --force --no-cache "$scene" --methods aniso_ssf --set aniso_ssf.filter=none,gaussian,narrow --reference analytic \
      -W $(quick 512 128) -H $(quick 512 128) --repeat 1 -q -o "$TMP/narrow_$view" 2> "$TMP/narrow_$view.log"
  pick "$view" "$TMP/narrow_$view/metrics.csv" >> "$csv.tmp"
done
publish "$csv"; stamp_csv "$csv"; column -t -s, "$csv"

csv=$OUT/doubts_curvature.csv
echo "size,variant,mask_iou,depth_bias_r,depth_rmse_r,interior_normal_mean_deg" > "$csv.tmp"
for size in $(quick "256 512 1024" "64 128"); do
  "$BIN" compare --force --no-cache experiments/scenes/box.json --methods aniso_ssf --set aniso_ssf.filter=curvature \
      --set aniso_ssf.iterations=80,320 --set aniso_ssf.anisotropy=off,on --reference analytic \
      -W $size -H $size --repeat 1 -q -o "$TMP/curv_$size" 2> "$TMP/curv_$size.log"
  pick "$size" "$TMP/curv_$size/metrics.csv" >> "$csv.tmp"
done
publish "$csv"; stamp_csv "$csv"; column -t -s, "$csv"
