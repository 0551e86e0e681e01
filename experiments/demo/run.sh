#!/usr/bin/env bash
# The main job's committed summary, results/demo/: `fluidsurf compare` of every registered
# method on the bundled SPlisHSPlasH dam break (24,389 particles, 512x512) against the exact
# reference, the run scripts/demo.sh makes (mesh twice: mesh.field=isotropic,zhu_bridson,
# the second Zhu & Bridson's surface). The whole run (every PNG, EXR and heatmap) goes
# to out/demo_study/ (git-ignored); results/demo/ keeps metrics.csv, timings.csv, report.md,
# panel_small.png (half size), README.md's table (experiments/tools/csv_table.py) and
# report.html with the PNGs it shows (each view, its own appearance, the heatmaps: about 6 MB),
# rebuilt there by `fluidsurf report` so the page embeds exactly the files beside it.
# results/demo/ changes only when this script runs: run it at a clean commit (as
# experiments/run_all.sh does, after you commit), so its CSVs name that commit with dirty=0.
# FS_QUICK=1 (experiments/lib.sh): 128x128, one run, into out/quick/results/demo, README alone.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, stamp_csv
BIN=${BIN:-./build/fluidsurf}
OUT=$RESULTS/demo
TMP=out/$(quick "" quick/)demo_study
[ -x "$BIN" ] || { echo "demo/run.sh: $BIN missing: bash scripts/build.sh build" >&2; exit 2; }
mkdir -p "$OUT" "$(dirname "$TMP")"
# --force: the folder is this study's own, remade on every run
"$BIN" compare --force --no-cache experiments/scenes/dam_break.json $(quick "" "-W 128 -H 128 --repeat 1") -o "$TMP" \
  $(zb_sweep "$BIN")
cp "$TMP/metrics.csv" "$TMP/timings.csv" "$TMP/report.md" "$OUT/"
stamp_csv "$OUT/metrics.csv" "$OUT/timings.csv" # fluidsurf's provenance names the commit already
oiiotool "$TMP/panel.png" --resize 50% -o "$OUT/panel_small.png"
for f in "$TMP"/*.png; do [ "$(basename "$f")" = panel.png ] || cp "$f" "$OUT/"; done
"$BIN" report "$OUT"
[ "$FS_QUICK" = 1 ] || python3 experiments/tools/csv_table.py "$OUT/metrics.csv" "$OUT/README.md"
echo "demo: wrote $OUT/ (metrics.csv, timings.csv, report.md, report.html and its PNGs, panel_small.png); the whole run is in $TMP/"
