#!/usr/bin/env bash
# Which splat path a CPU renderer prefers (issue 47): the sprite passes of spheres, raycast_pca
# and aniso_ssf on the raster pipeline (splat=raster, the papers') against the compute splatter
# (splat=compute, docs/DESIGN.md "The compute splatter"), over particle counts and image sizes,
# on this machine's GL (llvmpipe: the GLSL runs on the CPU, so this says nothing about a GPU;
# experiments/gpu/run.sh times both paths there).
#
#   experiments/bench/splat.sh          boxes of 20^3, 40^3, 60^3 at 128^2 and 256^2, 3 runs;
#                                       writes results/bench/splat.csv and README-splat.md
#   experiments/bench/splat.sh --quick  (or FS_QUICK=1) boxes of 12^3 and 20^3 at 96^2, 1 run,
#                                       into out/quick/results/bench/
#
# Synthetic lattice boxes (r = 0.025, jitter 0.1 r, auto-framed), each method with its defaults
# but the path. experiments/tools/render_bench times each variant and size in one process
# (one warm-up render, then RUNS timed ones). Environment: BIN (./build), SIDES, SIZES, RUNS.
# Time it on a quiet machine (/work/bin/quiet) at a clean commit.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; fi
source experiments/lib.sh # quick, RESULTS, STUDY_PROV, stamp_csv
BIN=${BIN:-./build}
RB=$BIN/experiments/render_bench
SIDES=${SIDES:-$(quick "20 40 60" "12 20")}
SIZES=${SIZES:-$(quick 128,256 96)}
RUNS=${RUNS:-$(quick 3 1)}
OUT=$RESULTS/bench
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"
[ -x "$RB" ] || { echo "splat.sh: $RB missing (build first)" >&2; exit 2; }

csv=$T/splat.csv
{ echo "# $STUDY_PROV; tool=experiments/bench/splat.sh; runs=$RUNS; $("$RB" --probe | head -1)"
  echo "label,particles,method,variant,size,run,stage,ms,gpu_ms,renderer,gl_version"; } > "$csv"
for side in $SIDES; do
  scene=$T/box_$side.json
  printf '{"particles": {"synthetic": "box", "size": [%d, %d, %d], "jitter": 0.1, "seed": 1}, "radius": 0.025}\n' \
    "$side" "$side" "$side" > "$scene"
  for m in spheres raycast_pca aniso_ssf; do
    echo "splat: box $side^3, $m" >&2
    "$RB" "$scene" "box_$side" "$m" "$SIZES" "$RUNS" "$m.splat=raster" "$m.splat=compute" >> "$csv"
  done
done
stamp_csv "$csv"
cp "$csv" "$OUT/splat.csv"
python3 experiments/bench/splat_report.py "$OUT/splat.csv" > "$T/README-splat.md"
cp "$T/README-splat.md" "$OUT/README-splat.md"
echo "splat: wrote $OUT/splat.csv and README-splat.md" >&2
