#!/usr/bin/env bash
# xiao2017 Fig. 5 analogue: raycast_pca beside every other registered method (the
# paper's screen-space and anisotropic screen-space rendering: spheres, aniso_ssf)
# on the dam break, against the exact reference, shipped defaults; and the paper's plain
# screen-space fluid rendering (van der Laan et al. 2009: isotropic sprites, curvature
# flow), which is aniso_ssf with anisotropy off and filter curvature.
# Writes results/xiao2017/fig5_panel.png (downscaled), fig5_metrics.csv (the plain SSF
# rows last), small single images fig5_<method>.png, fig5_ssf.png, and fig5_paper_row.png
# (the paper's three: SSF, anisotropic SSF, raycast_pca, after the reference). A single
# --set value names no variant, so the plain SSF rows get theirs here.
# Full outputs in out/xiao2017/fig5/ and fig5_ssf/.
# FS_QUICK=1 (experiments/lib.sh): 128^2, into out/quick/results/xiao2017 and out/quick/xiao2017/fig5.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 768 128)}
OUT=$RESULTS/xiao2017
W=out/$(quick "" quick/)xiao2017
TMP=$W/fig5
mkdir -p "$OUT" "$W"
[ -x "$BIN" ] || { echo "fig5.sh: $BIN missing" >&2; exit 2; }
# every registered method, as `fluidsurf methods` lists them (first word of each line)
methods=$("$BIN" methods | awk '/^[^ ]/ && $1 != "reference" { print $1 }' | paste -sd,)
"$BIN" compare --force --no-cache experiments/scenes/dam_break.json --methods "$methods" -W "$SIZE" -H "$SIZE" --repeat 1 \
    -o "$TMP" 2> "$W/fig5.log"
"$BIN" compare --force --no-cache experiments/scenes/dam_break.json --methods aniso_ssf --set aniso_ssf.anisotropy=off \
    --set aniso_ssf.filter=curvature -W "$SIZE" -H "$SIZE" --repeat 1 -o "$TMP"_ssf 2> "$W/fig5_ssf.log"
{ cat "$TMP/metrics.csv"; awk -F, -v OFS=, '!/^#/ && $1 == "aniso_ssf" { $2 = "anisotropy=off;filter=curvature"; print }' "$TMP"_ssf/metrics.csv; } > "$OUT/fig5_metrics.csv"
stamp_csv "$OUT/fig5_metrics.csv"
oiiotool "$TMP"_ssf/aniso_ssf.png --resize "$(quick 256x256 128x128)" -o "$OUT/fig5_ssf.png"
frames_mosaic "$OUT/fig5_paper_row.png" 4x1 "$(quick 384x384 64x64)" "$TMP/reference.png" "$TMP"_ssf/aniso_ssf.png \
    "$TMP/aniso_ssf.png" "$TMP/raycast_pca.png"
oiiotool "$TMP/panel.png" --resize "$(quick 1600x0 640x0)" -o "$OUT/fig5_panel.png" # 8 columns: legible at 1600
for m in reference ${methods//,/ }; do oiiotool "$TMP/$m.png" --resize "$(quick 256x256 128x128)" -o "$OUT/fig5_$m.png"; done
echo "wrote $OUT/fig5_*"
