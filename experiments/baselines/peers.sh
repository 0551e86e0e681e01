#!/usr/bin/env bash
# The peers study (issue 38): what a splashsurf or OpenVDB user runs in 2026 against the
# reference, on the reference studies' frames (reference_frames: the DualSPHysics frame,
# fluidsurf's splash frame, the bundled dam break). Variants: mesh with each smoothing
# (off, laplacian, taubin, weighted = splashsurf's recipe, 25 steps each, as its README),
# levelset with each rasteriser (particles = ParticlesToLevelSet, spheres =
# points::rasterizeSpheres, smooth = points::rasterizeSmoothSpheres), and mesh of Zhu &
# Bridson's field (mesh.field=zhu_bridson, unsmoothed). Each is rendered at
# SIZE^2 beside the reference and measured by peers_regions.py: the whole-image metrics of
# fluidsurf diff, the share of the reference's thin pixels (thickness under 4 r) each keeps,
# and its normal error on flat water. Times are the render's wall seconds in this run (one
# run; not a timing study: run the full study on a quiet machine).
#
#   experiments/baselines/peers.sh [--quick] [-o DIR]
#
# --quick (or FS_QUICK=1): 96x96, the splash and dam break frames only, into
# out/quick/results/baselines/peers. Full: 512x512 with the DualSPHysics frame (SHARED),
# into results/baselines/peers. Writes peers.csv (its first line names the commit) and
# README.md with the table generated from it. vdb_tool's own pipeline is timed beside
# levelset by experiments/baselines/run.sh (render.csv), not here.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; shift; fi
source experiments/lib.sh # quick, RESULTS, reference_frames, stamp_csv, exr_attr, replace_block
OUT=$RESULTS/baselines/peers
while [ $# -gt 0 ]; do
  case $1 in
    -o) OUT=$2; shift 2 ;;
    *) echo "usage: $0 [--quick] [-o DIR]" >&2; exit 2 ;;
  esac
done
BIN=${BIN:-./build/fluidsurf}
SIZE=$(quick 512 96)
[ -x "$BIN" ] || { echo "peers.sh: $BIN missing (build first)" >&2; exit 1; }
for t in oiiotool iinfo python3; do command -v $t > /dev/null || { echo "peers.sh: $t is needed" >&2; exit 1; }; done
reference_frames
variants=("mesh|off|mesh.smooth=off"
          "mesh|laplacian|mesh.smooth=laplacian mesh.smooth_iters=25"
          "mesh|taubin|mesh.smooth=taubin mesh.smooth_iters=25"
          "mesh|weighted|mesh.smooth=weighted mesh.smooth_iters=25"
          "levelset|particles|levelset.rasterizer=particles"
          "levelset|spheres|levelset.rasterizer=spheres"
          "levelset|smooth|levelset.rasterizer=smooth"
          "mesh|zhu_bridson|mesh.field=zhu_bridson mesh.smooth=off")
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
csv=$tmp/peers.csv
echo "# $STUDY_PROV; size=$SIZE; cores=$(nproc); date=$(date -u +%F)" > "$csv"
echo "frame,method,variant,seconds,mask_iou,depth_bias_r,depth_p95_r,normal_mean_deg,interior_normal_mean_deg,thin_px,thin_kept,flat_px,flat_normal_deg" >> "$csv"
for f in "${frames[@]}"; do
  IFS='|' read -r name _ input <<< "$f"
  read -r -a in <<< "$input" # the input and its options (--up, --radius)
  ref=$tmp/$name.reference.exr
  "$BIN" render "${in[@]}" --method reference -W "$SIZE" -H "$SIZE" -q -o "$ref"
  r=$(exr_attr "$ref" r)
  for v in "${variants[@]}"; do
    IFS='|' read -r method variant sets <<< "$v"
    args=()
    for s in $sets; do args+=(--set "$s"); done
    exr=$tmp/$name.$method.$variant.exr
    t0=$(date +%s.%N)
    "$BIN" render "${in[@]}" --method "$method" "${args[@]}" -W "$SIZE" -H "$SIZE" -q -o "$exr"
    t1=$(date +%s.%N)
    row=$(python3 experiments/baselines/peers_regions.py "$BIN" "$exr" "$ref" "$r")
    echo "$name,$method,$variant,$(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", b - a}'),$row" >> "$csv"
    echo "peers.sh: $name $method $variant: $row" >&2
  done
done
cp "$csv" "$OUT/peers.csv"
bash experiments/baselines/peers_report.sh "$OUT"
