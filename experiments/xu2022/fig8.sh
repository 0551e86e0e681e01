#!/usr/bin/env bash
# xu2022 Fig. 8 analogue: the four filters (gaussian, bilateral, curvature flow,
# narrow-range; anisotropy on, shipped defaults) on a transparent fluid. The dam
# break under the scene's water material (Fresnel reflection, refraction through
# the thickness, absorption: common/eval/shading.c) at SIZE^2 (default 512) against
# the exact `reference`. Besides the G-buffer metrics, experiments/tools/highlights
# measures the paper's second claim, that narrow-range's highlight "forms an obvious
# bright area": how much of each image's specular highlight lies in broad areas
# rather than speckle, beside the reference's own.
# Writes results/xu2022/fig8.csv and fig8_row.png (reference, then the four filters,
# cropped and shrunk). Full outputs stay in out/xu2022/fig8/.
# FS_QUICK=1 (experiments/lib.sh): 128^2, into out/quick/results/xu2022.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/highlights}
SIZE=${SIZE:-$(quick 512 128)}
OUT=$RESULTS/xu2022
TMP=out/$(quick "" quick/)xu2022/fig8
mkdir -p "$OUT" "$TMP"
for x in "$BIN" "$TOOL"; do
  [ -x "$x" ] || { echo "fig8.sh: $x missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
done
FILTERS="gaussian bilateral curvature narrow"
"$BIN" compare --no-cache experiments/scenes/dam_break.json --methods aniso_ssf --set aniso_ssf.anisotropy=on \
    --set "aniso_ssf.filter=${FILTERS// /,}" --reference reference -W "$SIZE" -H "$SIZE" --repeat 1 \
    -o "$TMP" -q 2> "$TMP/compare.log"
exrs=("$TMP/reference.exr")
for f in $FILTERS; do exrs+=("$TMP/aniso_ssf_anisotropy=on_filter=$f.exr"); done
"$TOOL" "${exrs[@]}" > "$TMP/highlights.csv"
# fig8.csv: one row per image, the metrics against the reference beside the highlight layout
{
  sed -n '1s/^# *\(.*\)$/# \1 highlights: experiments\/tools\/highlights (luminance >= 1, areas >= 16 px)/p' "$TMP/metrics.csv"
  echo "image,interior_normal_mean_deg,normal_p95_deg,psnr_db,ssim,highlight_pct,areas,largest_px,share_in_large_pct"
  awk -F, -v dir="$TMP/" '
    FNR == 1 && NR == 1 { next }
    NR == FNR { if ($0 !~ /^#/ && $1 != "method") { split($2, v, "filter="); m[v[2]] = $11 "," $10 "," $12 "," $13 } ; next }
    FNR == 1 { next }
    { f = $1; sub(dir, "", f); sub(/\.exr$/, "", f); key = f; sub(/.*filter=/, "", key)
      name = (f == "reference") ? "reference" : key
      print name "," (f == "reference" ? ",,," : m[key]) "," $4 "," $5 "," $6 "," $7 }' \
    "$TMP/metrics.csv" "$TMP/highlights.csv"
} > "$OUT/fig8.csv"
# the row: reference, then the four filters, each cropped to the wave and shrunk
crop=$(awk -v s="$SIZE" 'BEGIN {f = s / 512; printf "%dx%d+%d+%d", 400 * f, 400 * f, 50 * f, 30 * f}')
args=()
for e in "${exrs[@]}"; do args+=("${e%.exr}.png" --cut "$crop" --resize "$(quick 220x220 64x64)"); done
oiiotool "${args[@]}" --mosaic 5x1 --ch R,G,B -o "$OUT/fig8_row.png"
echo "wrote $OUT/fig8.csv, $OUT/fig8_row.png"
