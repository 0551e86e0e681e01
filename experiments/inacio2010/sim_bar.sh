#!/usr/bin/env bash
# Simulator bar of issue 7: dam break, r = 0.025, Tait, at least 8k particles,
# 300 frames of 1/60 s on the CPU and on the GPU path: no NaN, no particle
# outside the container, no safety clamp; at the end (t = 5 s) the mean density
# error <= 3% and the water depth within 5% of the depth its volume implies.
# Writes results/inacio2010/sim_bar.csv and the per-frame records
# sim_bar_<path>_frames.csv. On OSMesa the GPU path runs on the CPU cores too
# (llvmpipe): the renderer is in every row.
# Usage: experiments/inacio2010/sim_bar.sh [BIN]   (FRAMES, PARTICLES, PARALLEL=1 override)
set -uo pipefail
cd "$(dirname "$0")/../.."
BIN=${1:-build/fluidsurf}
FRAMES=${FRAMES:-300}
PARTICLES=${PARTICLES:-8000}
OUT=results/inacio2010
mkdir -p "$OUT"
csv=$OUT/sim_bar.csv
tmp=$(mktemp)
echo "# fluidsurf simulate dam_break --particles $PARTICLES --eos tait --frames $FRAMES; $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)" > "$tmp"
echo "path,renderer,particles,boundary,frames,t_end,steps,wall_s,ms_per_step,steps_per_s,exit,nonfinite,outside_max,clamps,violations,dt_min,dt_max,density_err,density_abs_err,depth,depth_expected,depth_rel_err,kinetic,pass" >> "$tmp"
# PARALLEL=1 runs the two paths at the same time (each then shares the cores).
sim() { # PATH
  local start=$(date +%s.%N)
  "$BIN" simulate dam_break --particles "$PARTICLES" --eos tait --frames "$FRAMES" --$1 -q \
    --stats "$OUT/sim_bar_$1_frames.csv"
  echo $? "$(echo "$(date +%s.%N) - $start" | bc -l)" > "$tmp.$1"
}
if [ "${PARALLEL:-0}" = 1 ]; then
  sed -i '1s/$/; cpu and gpu paths ran concurrently/' "$tmp"
  sim cpu & sim gpu & wait
else
  sim cpu; sim gpu
fi
for path in cpu gpu; do
  frames=$OUT/sim_bar_${path}_frames.csv
  read rc wall < "$tmp.$path"
  rm -f "$tmp.$path"
  awk -F, -v path=$path -v rc=$rc -v wall=$wall -v frames=$FRAMES '
    /^# / { if (match($0, /renderer [^;]*/)) renderer = substr($0, RSTART + 9, RLENGTH - 9);
            if (match($0, /\+ [0-9]+ boundary/)) nb = substr($0, RSTART + 2, RLENGTH - 11); next }
    $1 == "frame" { next }
    { steps += $4; ms += $17; if ($11 > out) out = $11; last = $0; if ($5 != "inf" && ($5 < dtmin || dtmin == "")) dtmin = $5; if ($6 > dtmax) dtmax = $6 }
    END {
      split(last, f, ",");
      nonfinite = (rc != 0) ? 1 : 0;
      rel = (f[15] > 0) ? f[14] / f[15] - 1 : 0;
      ok = (rc == 0 && f[1] == frames && out == 0 && f[10] == 0 && f[12] <= 0.03 && (rel < 0 ? -rel : rel) <= 0.05);
      printf "%s,\"%s\",%s,%s,%s,%s,%d,%.1f,%.3f,%.1f,%d,%d,%d,%s,%s,%s,%s,%s,%s,%s,%s,%.4f,%s,%s\n",
        path, renderer, f[3], nb, f[1], f[2], steps, wall, ms / steps, steps / (ms / 1000), rc, nonfinite, out,
        f[10], f[8], dtmin, dtmax, f[12], f[13], f[14], f[15], rel, f[16], ok ? "yes" : "no" }' "$frames" >> "$tmp"
done
mv "$tmp" "$csv"
column -s, -t < "$csv"
