#!/usr/bin/env bash
# iwasaki2006 Fig. 7 analogue: the scene of Fig. 6 (surfels.sh's dam break) from a second
# viewpoint (dam_break_side.json: the other side, higher up), surfels with caustics in
# their own appearance and in the shared shading, beside `reference`, with the metrics.
# Writes results/iwasaki2006/fig7_{metrics.csv,own.png,shared.png,reference.png,panel.png}.
# FS_QUICK=1 (run_all.sh --quick): 128^2 into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
R=$RESULTS/iwasaki2006
mkdir -p "$R"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$BIN" compare --no-cache experiments/iwasaki2006/dam_break_side.json --methods surfels -W "$SIZE" -H "$SIZE" \
    --repeat 1 -q -o "$tmp/side"
cp "$tmp/side/metrics.csv" "$R/fig7_metrics.csv"
stamp_csv "$R/fig7_metrics.csv"
cp "$tmp/side/surfels_own.png" "$R/fig7_own.png"
cp "$tmp/side/surfels.png" "$R/fig7_shared.png"
cp "$tmp/side/reference.png" "$R/fig7_reference.png"
oiiotool "$tmp/side/panel.png" --resize "$(quick 640x0 320x0)" -o "$R/fig7_panel.png"
echo "wrote $R/fig7_*"
