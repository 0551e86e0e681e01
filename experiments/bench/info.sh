#!/usr/bin/env bash
# `fluidsurf info` on files without a radius (issue 16): the whole-process time on a
# 1M-particle frame (target: at most 2 s) and the radius it estimates from the spacing
# against the radius the particles were made with (targets: within 10% on a
# near-lattice frame, within 20% on a developed splash frame); and on every bundled
# SPlisHSPlasH frame and, in full mode, the shared DualSPHysics frame (issue 53), the
# estimate against the r their simulations used (0.025 and 0.00365, their READMEs), the
# spread README.md's radius sentence quotes (no target: kind "frame").
#
#   experiments/bench/info.sh           medians of 5 runs; writes results/bench/info.csv
#   experiments/bench/info.sh --quick   (or FS_QUICK=1, run_all.sh --quick) 1 run, a 27k box
#                                       and the splash frame, into out/quick/results/bench/
#
# Sets: the jittered lattice boxes of experiments/scenes (100k, 1M; r = 0.025 on a 2r
# lattice) and the committed splash frame of fluidsurf's own dam-break simulation
# (experiments/data/splash, 100k, r in its header). Each is written as a PLY with the
# radius comment removed, so info must estimate it. Environment: RUNS, BIN, SHARED (the
# shared data folder, default ../shared/data; full mode exits 2 without its frame).
set -euo pipefail
cd "$(dirname "$0")/../.."
quick=0
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; fi
source experiments/lib.sh # quick, RESULTS
[ "$FS_QUICK" = 1 ] && quick=1
BIN=${BIN:-./build/fluidsurf}
RUNS=${RUNS:-$(quick 5 1)}
OUT=$RESULTS/bench
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"

# writes $2 from $1 (a scene or particle file) as a binary PLY without a radius
strip_radius() {
  "$BIN" convert "$1" -o "$T/with_r.ply" 2> /dev/null
  python3 - "$T/with_r.ply" "$2" <<'EOF'
import sys
b = open(sys.argv[1], 'rb').read()
end = b.index(b'end_header\n') + len(b'end_header\n')
head = b''.join(l + b'\n' for l in b[:end].split(b'\n') if l and not l.startswith(b'comment radius'))
open(sys.argv[2], 'wb').write(head + b[end:])
EOF
}
# the radius the last strip_radius's input was made with: $1 when given, else the file's
true_radius() { [ -n "$1" ] && echo "$1" || "$BIN" info "$T/with_r.ply" | sed -n 's/^radius r: \([0-9.e-]*\).*/\1/p'; }

if [ $quick = 1 ]; then # a 30^3 box like box_100k's, and the splash frame (info reads 100k in well under a second)
  sed 's/"size": \[46, 46, 46\]/"size": [30, 30, 30]/' experiments/scenes/box_100k.json > "$T/box_27k.json"
  grep -q '"size": \[30, 30, 30\]' "$T/box_27k.json" || { echo "info: no box size in box_100k.json" >&2; exit 1; }
  sets=("box_27k:$T/box_27k.json:lattice" "splash_100k:experiments/data/splash/dam_break_splash_100k.ply:developed")
else
  sets=("box_100k:experiments/scenes/box_100k.json:lattice" "splash_100k:experiments/data/splash/dam_break_splash_100k.ply:developed")
  sets+=("box_1m:experiments/scenes/box_1m.json:lattice")
  dsph=${SHARED:-../shared/data}/dualsphysics/dambreak200k_t0.300.vtk
  [ -f "$dsph" ] || { echo "info.sh: $dsph missing (set SHARED to the shared data folder)" >&2; exit 2; }
  sets+=("dualsphysics_t0.300:$dsph:frame:0.00365")
fi
d=experiments/data/splashsurf # SPlisHSPlasH's r = 0.025 (its README)
for f in dam_break_frame_23_24389_particles.vtk double_dam_break_frame_01_4732_particles.vtk \
         double_dam_break_frame_26_4732_particles.vtk cube_2366_particles.vtk dam_break_frame_9_6859_particles.bgeo; do
  sets+=("$(echo "$f" | sed 's/_particles.*//; s/_[0-9]*$//'):$d/$f:frame:0.025")
done
csv=$T/info.csv
echo "set,kind,particles,true_r,estimated_r,ratio,target,info_s_median,info_s_min,info_s_max,runs" > "$csv"
for s in "${sets[@]}"; do
  IFS=: read -r name src kind r_given <<< "$s"
  echo "info: $name" >&2
  strip_radius "$src" "$T/$name.ply"
  r_true=$(true_radius "$r_given")
  times=()
  for _ in $(seq "$RUNS"); do
    t0=$(date +%s.%N)
    "$BIN" info "$T/$name.ply" > "$T/info.txt" 2> /dev/null
    times+=("$(echo "$(date +%s.%N) - $t0" | bc -l)")
  done
  r_est=$(sed -n 's/^radius r: \([0-9.e-]*\) (estimated.*/\1/p' "$T/info.txt")
  n=$(sed -n 's/^particles: //p' "$T/info.txt")
  [ -n "$r_est" ] || { echo "info: $name: no estimated radius in the output" >&2; exit 1; }
  target=$(case $kind in lattice) echo 0.10 ;; developed) echo 0.20 ;; *) echo "" ;; esac)
  printf '%s\n' "${times[@]}" | sort -g > "$T/t"
  python3 - "$name" "$kind" "$n" "$r_true" "$r_est" "$target" "$T/t" >> "$csv" <<'EOF'
import statistics, sys
name, kind, n, rt, re, target, tf = sys.argv[1:]
t = [float(x) for x in open(tf)]
print(f"{name},{kind},{n},{rt},{re},{float(re) / float(rt):.4f},{target},{statistics.median(t):.3f},{min(t):.3f},{max(t):.3f},{len(t)}")
EOF
done
{ echo "# $("$BIN" --version), $(nproc) cores, info on PLY files without a radius; whole-process wall time"; cat "$csv"; } > "$OUT/info.csv"
stamp_csv "$OUT/info.csv"
cat "$OUT/info.csv"
# the table of README-info.md, written from the CSV (full mode only)
[ $quick = 1 ] && exit 0
{
  echo "# \`fluidsurf info\` without a radius"
  echo
  echo "Written by \`experiments/bench/info.sh\` from \`info.csv\`: $(head -1 "$OUT/info.csv" | sed 's/^# //')."
  echo "The estimate is r = 0.5 (volume per particle)^(1/3) from the 32 nearest neighbours of"
  echo "4096 sampled particles; targets: within 10% of the true r on a lattice, 20% on a developed frame, info on 1M in at most 2 s."
  echo "The simulations' own frames (kind frame: the bundled SPlisHSPlasH ones at r = 0.025, the DualSPHysics one at"
  echo "r = 0.00365) have no target: their spread is what README.md's radius sentence quotes."
  echo
  echo "| set | kind | particles | true r | estimated r | ratio | target | info, s (median of runs) |"
  echo "|---|---|---|---|---|---|---|---|"
  grep -v '^#' "$OUT/info.csv" | tail -n +2 | awk -F, '{printf "| %s | %s | %s | %s | %s | %s | %s | %s (%s) |\n", $1, $2, $3, $4, $5, $6, $7 == "" ? "-" : "+/-" $7, $8, $11}'
} > "$OUT/README-info.md"
