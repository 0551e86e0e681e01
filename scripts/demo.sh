#!/usr/bin/env bash
# The main job: sets up, builds, and compares every registered method on the
# bundled SPlisHSPlasH dam break (24,389 particles) against the exact reference.
# Writes results/demo/: panel.png, report.md, metrics.csv, timings.csv, one
# PNG + EXR (G-buffer, provenance) per method, diff_*.png heatmaps.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
source experiments/lib.sh # FS_QUICK=1 (experiments/run_all.sh --quick): 128x128 into out/quick/results
out=$RESULTS/demo
./build/fluidsurf compare --no-cache experiments/scenes/dam_break.json -o "$out" $(quick "" "-W 128 -H 128 --repeat 1") "$@"
# the half-size copy that the repository keeps (results/demo/ is otherwise not committed)
oiiotool "$out/panel.png" --resize 50% -o "$out/panel_small.png"
[ "$FS_QUICK" = 1 ] || python3 experiments/tools/csv_table.py "$out/metrics.csv" "$out/README.md"
echo "see $out/panel.png and $out/report.md"
