#!/usr/bin/env bash
# The main job: sets up, builds, and compares every registered method on the
# bundled SPlisHSPlasH dam break (24,389 particles) against the exact reference.
# Writes results/demo/: panel.png, report.md, metrics.csv, timings.csv, one
# PNG + EXR (G-buffer, provenance) per method, diff_*.png heatmaps.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
./build/fluidsurf compare --no-cache experiments/scenes/dam_break.json -o results/demo "$@"
# the half-size copy that the repository keeps (results/demo/ is otherwise not committed)
oiiotool results/demo/panel.png --resize 50% -o results/demo/panel_small.png
echo "see results/demo/panel.png and results/demo/report.md"
