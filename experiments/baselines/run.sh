#!/usr/bin/env bash
# The baselines study (issue 15): levelset and mesh against the reference on the
# bundled dam break, the mesh's convergence as cube shrinks, and the speed and
# peak memory of `fluidsurf mesh` and `levelset` against OpenVDB's vdb_tool
# whole pipeline on the same frames, measured in the same run (medians of RUNS).
#
#   experiments/baselines/run.sh [-o DIR] [--sets "dam box_100k box_1m"]
#
# Writes DIR (default results/baselines): quality.csv, convergence.csv,
# speed.csv (one row per tool, set and run: wall s, peak RSS), stages.csv
# (fluidsurf mesh --timings), convergence.png, and README.md from them.
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT=results/baselines
SETS="dam box_100k box_1m"
while [ $# -gt 0 ]; do
  case $1 in
    -o) OUT=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    *) echo "usage: $0 [-o DIR] [--sets \"dam box_100k box_1m box_10m\"]" >&2; exit 2 ;;
  esac
done
BIN=${BIN:-./build/fluidsurf}
RUNS=${RUNS:-3}
[ -x "$BIN" ] || bash scripts/build.sh "$(dirname "$BIN")"
command -v vdb_tool > /dev/null || { echo "run.sh: vdb_tool (libopenvdb-tools) is needed" >&2; exit 1; }
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prov="# commit=$(git describe --always --dirty); cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); cores=$(nproc); vdb_tool=$(dpkg-query -W -f '${Version}' libopenvdb-tools 2>/dev/null || echo unknown); date=$(date -u +%F)"

# ---- quality: the dam break at 512x512, levelset and mesh (plain and Taubin) against the reference
"$BIN" compare experiments/scenes/dam_break.json --methods reference,levelset,mesh --no-cache -q --repeat 1 \
  -o "$tmp/q" > /dev/null
"$BIN" compare experiments/scenes/dam_break.json --methods mesh --set mesh.smooth=taubin --no-cache -q --repeat 1 \
  -o "$tmp/qs" > /dev/null
{ echo "$prov"; grep -v '^#' "$tmp/q/metrics.csv"; grep -v '^#' "$tmp/qs/metrics.csv" | awk -F, -v OFS=, 'NR > 1 && $1 == "mesh" {$2 = "smooth=taubin"; print}'; } > "$OUT/quality.csv"

# ---- convergence: mesh against the reference as cube shrinks from 1 r to 0.25 r
"$BIN" compare experiments/scenes/dam_break.json --methods mesh --set mesh.cube=1,0.75,0.5,0.35,0.25 --no-cache -q \
  --repeat 1 -o "$tmp/c" > /dev/null
{ echo "$prov"; grep -v '^#' "$tmp/c/metrics.csv" | awk -F, 'NR == 1 || $1 == "mesh"'; } > "$OUT/convergence.csv"
if command -v gnuplot > /dev/null; then
  awk -F, 'NR > 2 { split($2, a, "="); print a[2], $7, $8 }' "$OUT/convergence.csv" > "$tmp/conv.dat"
  gnuplot <<GP
set terminal pngcairo size 640,420
set output "$OUT/convergence.png"
set title "mesh against reference, dam break 512x512"
set xlabel "cube (multiples of r)"; set ylabel "depth error (r)"; set logscale xy; set key top left
plot "$tmp/conv.dat" using 1:2 with linespoints title "depth RMSE", "" using 1:3 with linespoints title "depth p95"
GP
fi

# ---- speed and memory: the same PLY for every tool; wall time and peak RSS of the whole process
set_file() { # NAME -> the PLY path
  case $1 in
    dam) echo experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply ;;
    *) [ -s "$tmp/$1.ply" ] || "$BIN" convert "experiments/scenes/$1.json" -o "$tmp/$1.ply" >&2; echo "$tmp/$1.ply" ;;
  esac
}
timed() { # SET TOOL RUN CMD...: appends a speed.csv row
  local set=$1 tool=$2 run=$3; shift 3
  /usr/bin/time -f "%e %M" -o "$tmp/time" "$@" > "$tmp/stdout" 2> "$tmp/stderr" || { echo "run.sh: $tool on $set failed: $(tail -2 "$tmp/stderr")" >&2; return 1; }
  read -r wall kb < "$tmp/time"
  echo "$set,$tool,$run,$N,$wall,$kb" >> "$OUT/speed.csv"
}
{ echo "$prov"; echo "set,tool,run,particles,wall_s,peak_rss_kb"; } > "$OUT/speed.csv"
{ echo "$prov"; echo "set,settings,run,frame,stage,ms,vertices,triangles"; } > "$OUT/stages.csv"
r=0.025
for set in $SETS; do
  ply=$(set_file "$set")
  N=$("$BIN" info "$ply" --radius $r | awk '/^particles:/ {print $2}')
  for run in $(seq 1 "$RUNS"); do
    # one run of each tool in turn, so load on the machine hits them alike
    timed "$set" "fluidsurf mesh" "$run" "$BIN" mesh "$ply" --radius $r -q --timings -o "$tmp/m.ply"
    sed "s/^/$set,cube=0.5,$run,/" "$tmp/stdout" | tail -n +2 >> "$OUT/stages.csv"
    timed "$set" "vdb_tool points2ls+ls2mesh" "$run" vdb_tool -read "$ply" -points2ls voxel=$(awk -v r=$r 'BEGIN {print r / 2}') radius=4 width=3 -ls2mesh -write "$tmp/v.ply"
    timed "$set" "vdb_tool points2ls" "$run" vdb_tool -read "$ply" -points2ls voxel=$(awk -v r=$r 'BEGIN {print r / 2}') radius=4 width=3
    timed "$set" "fluidsurf mesh cube=1.5" "$run" "$BIN" mesh "$ply" --radius $r -q --timings --set mesh.cube=1.5 -o "$tmp/m15.ply"
    sed "s/^/$set,cube=1.5,$run,/" "$tmp/stdout" | tail -n +2 >> "$OUT/stages.csv"
    timed "$set" "fluidsurf startup" "$run" "$BIN" --version
  done
done
bash experiments/baselines/report.sh "$OUT"
echo "run.sh: wrote $OUT"
