#!/usr/bin/env bash
# inacio2010 Fig. 9 analogue: the same scene at the same simulated time with more
# and more particles, rendered with volume_raycast side by side.
# The dam break (1 m column in a 2.4 x 1.6 x 1.0 m tank) is simulated to
# SIM_TIME seconds (default 1.0) with about N particles for each N in COUNTS; the
# tank stays the same and the particles get finer: r = 0.5 / cbrt(N) (0.025 at
# 8000), which is what "the same simulation with more particles" means (at a fixed
# r the simulator would grow the tank instead, and 1.0 s would be an earlier
# phase of a slower, bigger collapse). CPU path, Tait, the simulator's defaults
# (adaptive steps; the speed of sound follows the tank, so it is the same for all).
# Each last frame is rendered with `fluidsurf render --method volume_raycast`
# (grid_res GRID, default 256, the same for every count: as the paper, a fixed
# volume resolution), SIZE^2 (default 512), shared shading and the method's own
# opaque surface, the camera framing the fluid; the images are labelled with the
# particle count and put side by side.
# The same frames are rendered with `spheres` (radius r, shared shading), the paper's other
# half: ray casting against spheres at the same counts.
# Writes results/inacio2010/fig9_panel.png (shared shading), fig9_panel_own.png
# (the paper's opaque-surface look), fig9_panel_spheres.png (spheres), fig9_rows.png
# (ray casting above spheres) and fig9.csv (count, r, steps, wall time).
# Usage: experiments/inacio2010/fig9.sh [BIN]   (COUNTS, SIM_TIME, SIZE, GRID,
#        TIMEOUT_S (per simulation, default 1200), BIN= override)
# FS_QUICK=1 (run_all.sh --quick): 512 and 1024 particles, 0.05 s, 128^2, grid 64, into
# out/quick/results.
set -uo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${1:-${BIN:-build/fluidsurf}}
COUNTS=${COUNTS:-$(quick "1024 2048 4096 8192" "512 1024")} # the paper's counts; 32768 131072 add about 20 minutes
SIM_TIME=${SIM_TIME:-$(quick 1.0 0.05)}
SIZE=${SIZE:-$(quick 512 128)}
GRID=${GRID:-$(quick 256 64)}
TIMEOUT_S=${TIMEOUT_S:-$(quick 1200 60)}
OUT=$RESULTS/inacio2010
mkdir -p "$OUT"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
csv=$T/fig9.csv
echo "# fluidsurf simulate dam_break --particles N --radius R (fixed tank); $SIM_TIME s; CPU path; render volume_raycast grid_res $GRID, ${SIZE}x${SIZE}; $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)" > "$csv"
echo "particles_requested,particles,r,boundary,t,steps,sim_wall_s,render_ms,renderer,image,note" >> "$csv"
shared=() own=() spheres=()
for n in $COUNTS; do
  r=$(awk -v n="$n" 'BEGIN { printf "%.6g", 0.5 / exp(log(n) / 3) }')
  t0=$(date +%s.%N)
  # 10 frames of SIM_TIME / 10 (the steps adapt within each); files: frames 0..10
  timeout "$TIMEOUT_S" "$BIN" simulate dam_break --particles "$n" --radius "$r" --fps "$(awk -v t="$SIM_TIME" 'BEGIN { print 10 / t }')" \
    --frames 10 -q -o "$T/dam_${n}_%04d.bgeo" --stats "$T/stats_$n.csv"
  rc=$?
  wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  if [ $rc != 0 ] || [ ! -f "$T/dam_${n}_0010.bgeo" ]; then
    echo "$n,,$r,,,,$wall,,,,\"simulation failed or timed out (rc $rc, limit $TIMEOUT_S s): left out of the panel\"" >> "$csv"
    echo "fig9: $n: simulation rc $rc after $wall s" >&2
    continue
  fi
  np=$(prov "$T/stats_$n.csv" fluid_particles) nb=$(prov "$T/stats_$n.csv" boundary_particles)
  steps=$(awk -F, '$1 ~ /^[0-9]+$/ { s += $4; t = $2 } END { print s "," t }' "$T/stats_$n.csv")
  img=$T/fig9_$n.png
  "$BIN" render "$T/dam_${n}_0010.bgeo" --method volume_raycast --radius "$r" --set volume_raycast.grid_res="$GRID" \
    -W "$SIZE" -H "$SIZE" -q --timings -o "$img" > "$T/timings_$n.csv"
  "$BIN" render "$T/dam_${n}_0010.bgeo" --method volume_raycast --radius "$r" --set volume_raycast.grid_res="$GRID" \
    --set volume_raycast.thickness=off --appearance own -W "$SIZE" -H "$SIZE" -q -o "$T/fig9_${n}_own.png"
  rms=$(awk -F, '$1 != "stage" && $1 != "load" && $1 != "grid" && $1 != "upload" { s += $2 } END { printf "%.0f", s }' "$T/timings_$n.csv")
  # the renderer: the march row from the header's renderer column on (it holds commas)
  rend=$(awk -F, '$1 == "stage" { for (i = 1; i <= NF; i++) if ($i == "renderer") rc = i; next }
    $1 == "march" { s = $rc; for (i = rc + 1; i <= NF; i++) s = s "," $i; print s; exit }' "$T/timings_$n.csv")
  echo "$n,$np,$r,$nb,${steps#*,},${steps%,*},$wall,$rms,\"$rend\",fig9_panel.png," >> "$csv"
  label="$(echo "$np" | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta') particles, r = $(awk -v r="$r" 'BEGIN { printf "%.4f", r }') m"
  "$BIN" render "$T/dam_${n}_0010.bgeo" --method spheres --radius "$r" -W "$SIZE" -H "$SIZE" -q -o "$T/fig9_${n}_spheres.png"
  for v in "" _own _spheres; do
    oiiotool "$T/fig9_${n}${v}.png" --ch R,G,B --text:x=12:y=$((SIZE / 16)):size=$((SIZE / 20)):color=1,1,1:shadow=2:font=DejaVuSans "$label" \
      -o "$T/lab_${n}${v}.png"
  done
  shared+=("$T/lab_$n.png"); own+=("$T/lab_${n}_own.png"); spheres+=("$T/lab_${n}_spheres.png")
  echo "fig9: $n ($np particles, r $r): $wall s simulated, rendered" >&2
done
k=${#shared[@]}
if [ "$k" -gt 0 ]; then
  oiiotool "${shared[@]}" --mosaic "${k}x1" -o "$OUT/fig9_panel.png"
  oiiotool "${own[@]}" --mosaic "${k}x1" -o "$OUT/fig9_panel_own.png"
  oiiotool "${spheres[@]}" --mosaic "${k}x1" -o "$OUT/fig9_panel_spheres.png"
  oiiotool "${shared[@]}" "${spheres[@]}" --mosaic "${k}x2" --resize "$((k * 256))x512" -o "$OUT/fig9_rows.png"
fi
mv "$csv" "$OUT/fig9.csv"
stamp_csv "$OUT/fig9.csv"
if [ "$FS_QUICK" = 1 ] && [ "$k" -ne "$(wc -w <<< "$COUNTS")" ]; then echo "fig9: only $k of the counts $COUNTS rendered" >&2; exit 1; fi
column -s, -t < "$OUT/fig9.csv"
