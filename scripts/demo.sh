#!/usr/bin/env bash
# The main job: sets up, builds, and renders the bundled dam break with every
# method into out/demo/ (PNG for viewing, EXR with the G-buffer and provenance).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
mkdir -p out/demo
for m in spheres reference; do
  echo "== $m"
  ./build/fluidsurf render experiments/scenes/dam_break.json --method "$m" --timings -o "out/demo/dam_break_$m.png"
  ./build/fluidsurf render experiments/scenes/dam_break.json --method "$m" -o "out/demo/dam_break_$m.exr"
done
echo "images in out/demo/"
