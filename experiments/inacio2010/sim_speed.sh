#!/usr/bin/env bash
# Simulation speed, CPU path against GPU path (inacio2010 Tables I/II "Fluid
# Simulation" column): dam break with Tait at several particle counts, FRAMES
# frames of 1/60 s each, paths run one after the other. Reports ms per step and
# steps per second (step time only: no output, the per-frame measure excluded)
# with the renderer. On OSMesa the GPU path runs on llvmpipe, i.e. on the same
# CPU cores: this compares two implementations, not a CPU with a GPU.
# Writes results/inacio2010/sim_speed.csv.
# Usage: experiments/inacio2010/sim_speed.sh [BIN]   (BIN=, COUNTS, FRAMES override)
# FS_QUICK=1 (run_all.sh --quick): 1024 and 2048 particles, 2 frames, into out/quick/results.
set -uo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${1:-${BIN:-build/fluidsurf}}
COUNTS=${COUNTS:-$(quick "1024 2048 4096 8192 32768" "1024 2048")}
FRAMES=${FRAMES:-$(quick 10 2)}
OUT=$RESULTS/inacio2010
mkdir -p "$OUT"
T=$(mktemp -d)
csv=$OUT/sim_speed.csv tmp=$OUT/sim_speed.csv.tmp
echo "# fluidsurf simulate dam_break --eos tait --frames $FRAMES; $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)" > "$tmp"
echo "particles_requested,particles,boundary,path,renderer,threads,steps,step_ms_total,ms_per_step,steps_per_s,sim_s_per_wall_s" >> "$tmp"
for n in $COUNTS; do
  for path in cpu gpu; do
    "$BIN" simulate dam_break --particles "$n" --frames "$FRAMES" --$path -q --stats "$T/s.csv" || continue
    awk -F, -v req=$n -v path=$path -v renderer="$(prov "$T/s.csv" gl_renderer)" -v th="$(prov "$T/s.csv" threads)" \
        -v n="$(prov "$T/s.csv" fluid_particles)" -v nb="$(prov "$T/s.csv" boundary_particles)" '
      /^# / { next }
      $1 == "frame" || $1 == 0 { next }
      { steps += $4; ms += $17; t = $2 }
      END { printf "%s,%s,%s,%s,\"%s\",%s,%d,%.1f,%.3f,%.1f,%.4f\n", req, n, nb, path, renderer, th, steps, ms, ms / steps,
            1000 * steps / ms, t / (ms / 1000) }' "$T/s.csv" >> "$tmp"
  done
done
publish "$csv"
stamp_csv "$OUT/sim_speed.csv"
rm -rf "$T"
if [ "$FS_QUICK" = 1 ]; then # a quick run fails unless every run gave its row
  rows=$(grep -vc '^#\|^particles_requested' "$OUT/sim_speed.csv") want=$((2 * $(wc -w <<< "$COUNTS")))
  [ "$rows" -eq "$want" ] || { echo "sim_speed: $rows of the $want runs ran" >&2; exit 1; }
fi
column -s, -t < "$OUT/sim_speed.csv"
