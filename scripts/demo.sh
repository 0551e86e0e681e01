#!/usr/bin/env bash
# The main job: sets up, builds, and compares every registered method on the
# bundled SPlisHSPlasH dam break (24,389 particles) against the exact reference.
# Writes out/demo/ (git-ignored, so the clone stays clean): panel.png, report.md, report.html
# (the interactive comparison page, README.md "The comparison page"),
# metrics.csv, timings.csv, one PNG + EXR (G-buffer, provenance) per method,
# diff_*.png heatmaps; a second run replaces the first (--force). mesh runs twice, on
# the SPH field and on Zhu & Bridson's (mesh_field-zhu_bridson). Extra arguments
# go to compare. The committed copy in results/demo/ is made by
# experiments/demo/run.sh at a clean commit, never by this script.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# only the command the demo runs: the tests and tools come with scripts/test.sh
FS_BUILD_TARGET=fluidsurf bash scripts/build.sh build
source experiments/lib.sh # FS_QUICK=1 (experiments/run_all.sh --quick): 128x128 into out/quick/demo
out=out/$(quick "" quick/)demo
mkdir -p "$(dirname "$out")"
./build/fluidsurf compare --force --no-cache experiments/scenes/dam_break.json -o "$out" $(quick "" "-W 128 -H 128 --repeat 1") \
  $(zb_sweep ./build/fluidsurf) "$@"
echo "see $out/report.html (open it in a browser), $out/panel.png and $out/report.md"
