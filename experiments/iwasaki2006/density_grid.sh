#!/usr/bin/env bash
# iwasaki2006 section 4: the density grid by slice splatting (4 planes per RGBA32F
# pass, particles clustered into N_c = 16 height bands) against the exact CPU sum
# through the neighbour grid, at 128^3 and 256^3 (points along the longest axis;
# the grid spans the bounding box padded by H) on the 24k dam break and a 205k
# synthetic box. Writes results/iwasaki2006/density_grid.csv: medians of RUNS runs
# (default 3) per cell, the splat grid's relative L2 difference to the exact grid,
# the disks drawn (one per particle per 4-plane pass its band was drawn in) and
# the renderer. On OSMesa the renderer is llvmpipe: the "GPU" path runs on the
# same CPU cores as the C code, so the ratio is not a GPU speed-up (docs/DESIGN.md).
#
# Timed: exact_cpu = neighbour grid build + exact sum (OpenMP over planes);
# slice_splat = clustering + upload + all passes + read back, after one untimed
# warm-up run (shader compilation happens at the first draw on llvmpipe).
# FS_QUICK=1 (run_all.sh --quick): 1 run at 32 and 48 points, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, quick, RESULTS, study_commit
# BIN: density_bench itself, or (as run_all.sh exports it) fluidsurf, whose build's
# density_bench is then used
case ${BIN:-} in
  "") BIN=./build/experiments/density_bench ;;
  *density_bench) ;;
  *) BIN=$(dirname "$BIN")/experiments/density_bench ;;
esac
RUNS=${RUNS:-$(quick 3 1)}
RES=${RES:-$(quick "128 256" "32 48")}
OUT=$RESULTS/iwasaki2006
TMP=out/$(quick "" quick/)iwasaki2006/density_grid
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "density_grid.sh: $BIN missing: bash scripts/build.sh build" >&2; exit 2; }

# label:scene
SETS="dam_break_24k:experiments/scenes/dam_break.json
box_205k:experiments/scenes/box_200k.json"

csv=$OUT/density_grid.csv
load0=$(cut -d' ' -f1-3 /proc/loadavg)
{
  echo "# iwasaki2006 density grid: slice splatting (N_c = 16) vs exact CPU; $(study_commit); $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); renderer llvmpipe = OSMesa on the same CPU cores: no GPU timing"
  echo "# medians of $RUNS runs; res = grid points along the longest axis (dims in the raw rows under $TMP); exact_cpu includes the neighbour grid build; slice_splat includes clustering, upload and read back"
  echo "set,particles,res,method,ms_median,rel_l2_vs_exact,disks,renderer"
} > "$csv.tmp"

while IFS=: read -r label scene; do
  for res in $RES; do
    raw=$TMP/${label}_${res}.csv
    "$BIN" "$scene" "$label" "$res" "$RUNS" 16 > "$raw"
    for method in exact_cpu slice_splat; do
      rows=$(grep ",$method," "$raw")
      n=$(echo "$rows" | head -1 | cut -d, -f2)
      ms=$(echo "$rows" | cut -d, -f7 | median)
      l2=$(echo "$rows" | cut -d, -f8 | sort -g | tail -1) # worst run
      disks=$(echo "$rows" | head -1 | cut -d, -f9)
      renderer=$(echo "$rows" | head -1 | cut -d, -f10- | sed 's/,[0-9]*,[0-9.]*,"[^"]*"$//; s/,[0-9]*,,$//')
      [ "$method" = exact_cpu ] && l2=0
      echo "$label,$n,$res,$method,$ms,$l2,$disks,$renderer" >> "$csv.tmp"
      printf '%-14s %4s %-12s %10.1f ms  rel L2 %-9s disks %s\n' "$label" "$res" "$method" "$ms" "$l2" "${disks:--}"
    done
  done
done <<< "$SETS"
# The machine may be shared: the load averages before and after go into the header.
sed -i "2s|\$|; load average before: $load0, after: $(cut -d' ' -f1-3 /proc/loadavg)|" "$csv.tmp"
publish "$csv"
stamp_csv "$csv"
echo "wrote $csv"
