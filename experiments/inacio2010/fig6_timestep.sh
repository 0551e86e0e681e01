#!/usr/bin/env bash
# inacio2010 Fig. 6/7 analogue: one SPH step of 0.01 s per frame against ten
# steps of 0.001 s, dam break with 8192 particles (the paper's largest), 1 s of
# simulated time, CPU and GPU path. Two stiffnesses: our Tait default
# (c = 10x the expected peak speed, where even 0.001 s exceeds the CFL bound)
# and a soft ideal gas (k = 225 m^2/s^2, c = 15 m/s) for which 0.001 s steps are
# within the bound while the water is slow (not at the peak speeds of the
# collapse) and one 0.01 s step is 7.5x beyond it at rest, the regime the
# paper's interactive setting implies. Reports per run the bound, how many steps broke
# it, what happened (divergence to NaN: exit 1; particles held in only by the
# safety clamp; the peak speed) and the time per frame (renderer named).
# Writes results/inacio2010/fig6_timestep.csv.
# Usage: experiments/inacio2010/fig6_timestep.sh [BIN]   (BIN=, PARTICLES, SIM_SECONDS override)
# FS_QUICK=1 (run_all.sh --quick): 1024 particles, 0.1 s simulated, into out/quick/results.
set -uo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${1:-${BIN:-build/fluidsurf}}
PARTICLES=${PARTICLES:-$(quick 8192 1024)}
SECONDS_SIM=${SIM_SECONDS:-$(quick 1 0.1)}
OUT=$RESULTS/inacio2010
mkdir -p "$OUT"
T=$(mktemp -d)
csv=$OUT/fig6_timestep.csv
tmp=$csv.tmp
echo "# fluidsurf simulate dam_break --particles $PARTICLES, $SECONDS_SIM s simulated; $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)" > "$tmp"
echo "eos,stiffness,steps_x_dt,path,renderer,particles,bound_first_frame_s,bound_min_s,steps,violations,exit,frames_done,t_end,clamps,first_clamp_t,outside_max,v_max_peak,density_err_end,ms_per_frame_median,outcome" >> "$tmp"
run() { # EOS STIFFNESS_ARGS LABEL SUBSTEPS DT PATH
  local eos=$1 stiff=$2 sub=$4 dt=$5 path=$6
  local frames=$(echo "$SECONDS_SIM / ($sub * $dt) + 0.5" | bc -l | cut -d. -f1)
  local st=$T/${eos}_${sub}_${path}.csv
  "$BIN" simulate dam_break --particles "$PARTICLES" --eos "$eos" $stiff --dt "$dt" --substeps "$sub" --frames "$frames" \
    --$path -q --stats "$st" 2> "$T/err"
  local rc=$?
  [ -s "$st" ] || missing=$((missing + 1))
  local ms=$(awk -F, '$1 ~ /^[0-9]+$/ && $1 > 0 {print $18}' "$st" | median)
  awk -F, -v renderer="$(prov "$st" gl_renderer)" -v n="$(prov "$st" fluid_particles)" -v eos=$eos -v stiff="${stiff:-default c}" -v lab="${sub}x$dt" -v path=$path -v rc=$rc -v ms="$ms" -v err="$(head -c 200 "$T/err" | tr ',\n' '; ')" '
    /^# / { next }
    $1 == "frame" { next }
    $1 == 0 { next }
    { steps += $4; last = $0; if ($9 > vpk) vpk = $9; if ($10 > 0 && fc == "") fc = $2; if ($11 > out) out = $11; if (b0 == "") b0 = $7; frames = $1 }
    END {
      split(last, f, ",");
      outcome = rc != 0 ? "diverged: " err : (f[10] > 0 ? "held in by the safety clamp" : (f[8] > 0 ? "ran; bound broken" : "stable within the bound"));
      printf "%s,%s,%s,%s,\"%s\",%s,%s,%s,%d,%s,%d,%d,%s,%s,%s,%d,%s,%s,%s,\"%s\"\n", eos, stiff, lab, path, renderer, n,
        b0, f[7], steps, f[8], rc, frames, f[2], f[10], fc == "" ? "-" : fc, out, vpk, f[12], ms, outcome }' "$st" >> "$tmp"
}
missing=0 # runs that left no per-frame record (a quick run fails on them)
for path in cpu gpu; do
  for cfg in "1 0.01" "10 0.001"; do
    set -- $cfg
    run tait "" x "$1" "$2" $path
    run ideal "--sound-speed 15" x "$1" "$2" $path  # k = c^2 = 225
  done
done
publish "$csv"
stamp_csv "$csv"
rm -rf "$T"
if [ "$FS_QUICK" = 1 ] && [ $missing -gt 0 ]; then echo "fig6_timestep: $missing runs left no --stats record" >&2; exit 1; fi
column -s, -t < "$csv"
