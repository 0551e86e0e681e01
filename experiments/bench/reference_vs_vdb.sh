#!/usr/bin/env bash
# Issue 49's table, short: the whole process of the reference with thickness on (the default)
# and off, against OpenVDB's vdb_tool (points -> level set -> ray trace, as speed.sh runs it),
# on the shared DualSPHysics frame (z up, r = 0.00365) auto-framed and from above (lib.sh
# reference_frames), at SIZE x SIZE, the tools alternating in each run, medians of RUNS.
#
#   experiments/bench/reference_vs_vdb.sh   writes results/bench/reference_vs_vdb.csv
#
# Environment: BIN (./build/fluidsurf), RUNS (3), SIZE (1024), SHARED (../shared/data),
# VDB_TOOL (vdb_tool). Run it on a quiet machine (`quiet`). Rows: view,particles,size,tool,
# runs,wall_s_median,vdb_tool_over_tool (vdb_tool's median / this tool's: above 1 is faster).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, auto_camera, view_from_above, vdb_aperture, RESULTS, STUDY_PROV
BIN=${BIN:-./build/fluidsurf} RUNS=${RUNS:-3} SIZE=${SIZE:-1024} SHARED=${SHARED:-../shared/data}
VDB_TOOL=${VDB_TOOL:-vdb_tool}
DSPH=$SHARED/dualsphysics/dambreak200k_t0.300.vtk
[ -f "$DSPH" ] || { echo "reference_vs_vdb.sh: $DSPH missing (set SHARED)" >&2; exit 2; }
command -v "$VDB_TOOL" > /dev/null || { echo "reference_vs_vdb.sh: $VDB_TOOL not found (Debian libopenvdb-tools)" >&2; exit 2; }
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
part="\"particles\": \"$(realpath "$DSPH")\", \"up\": \"z\", \"radius\": 0.00365"
echo "{$part}" > "$T/auto.json"
"$BIN" convert "$T/auto.json" -o "$T/points.ply" # vdb_tool's input, untimed
n=$("$BIN" info "$T/points.ply" | sed -n 's/^particles: *\([0-9]*\).*/\1/p')

# scene VIEW: the view's scene file with its camera written out; sets P_EYE, P_TGT, P_UP, FOV, P_R
scene() {
  auto_camera "$BIN" "$T/auto.json" "$T"
  [ "$1" = auto ] || view_from_above z
  echo "{$part, \"camera\": {$P_CAMERA}}" > "$T/$1.json"
}
# timed NAME CMD...: the command's wall seconds appended to $T/NAME
timed() {
  local name=$1; shift
  /usr/bin/time -f %e -o "$T/time" "$@" > /dev/null
  cat "$T/time" >> "$T/$name"
}

tools="reference reference_thickness_off vdb_tool"
: > "$T/rows"
for view in auto above; do
  scene "$view"
  voxel=$(awk -v r="$P_R" 'BEGIN {printf "%.9g", r / 2}')
  for t in $tools; do : > "$T/$view.$t"; done
  for k in $(seq "$RUNS"); do
    timed "$view.reference" "$BIN" render "$T/$view.json" -W "$SIZE" -H "$SIZE" --method reference -q -o "$T/ref.exr"
    timed "$view.reference_thickness_off" "$BIN" render "$T/$view.json" -W "$SIZE" -H "$SIZE" --method reference \
      --set reference.thickness=off -q -o "$T/off.exr"
    timed "$view.vdb_tool" "$VDB_TOOL" -read "$T/points.ply" -points2ls voxel="$voxel" radius=4 width=3 \
      -render image="${SIZE}x$SIZE" translate="($P_EYE)" target="($P_TGT)" up="($P_UP)" aperture="$(vdb_aperture "$FOV")" \
      "$T/vdb.png"
    echo "reference_vs_vdb: $view, run $k: $(for t in $tools; do tail -1 "$T/$view.$t"; done | tr '\n' ' ')" >&2
  done
  vdb=$(median < "$T/$view.vdb_tool")
  for t in $tools; do
    m=$(median < "$T/$view.$t")
    echo "$view,$n,$SIZE,$t,$RUNS,$m,$(awk -v a="$vdb" -v b="$m" 'BEGIN {printf "%.3f", a / b}')" >> "$T/rows"
  done
done
{ echo "# $STUDY_PROV; tool=experiments/bench/reference_vs_vdb.sh; frame=$DSPH; vdb_tool: $(dpkg-query -W -f '${Package} ${Version}' libopenvdb-tools 2> /dev/null || echo unknown); load=$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "view,particles,size,tool,runs,wall_s_median,vdb_tool_over_tool"; cat "$T/rows"; } > "$T/out.csv"
mkdir -p "$RESULTS/bench"
mv "$T/out.csv" "$RESULTS/bench/reference_vs_vdb.csv"
echo "reference_vs_vdb: wrote $RESULTS/bench/reference_vs_vdb.csv" >&2
