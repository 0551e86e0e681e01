#!/usr/bin/env bash
# inacio2010 Fig. 7 analogue: screenshots at the same simulated time of one SPH step of
# 0.01 s per frame against ten steps of 0.001 s (dam break, 8192 particles, the soft
# ideal gas of fig6_timestep.sh: k = 225 m^2/s^2, for which 0.001 s steps are within the
# CFL bound and one 0.01 s step is not). Both end states are rendered by volume_raycast
# in its own appearance under one camera (auto-framed on the ten-step state).
# Writes results/inacio2010/fig7_pair.png (1 x 0.01 s, 10 x 0.001 s) and fig7.csv (per
# run: the last frame's particles held in by the safety clamp so far, peak speed, and
# the top of the fluid's bounding box, the splash's height).
# Work in out/inacio2010/fig7/. FS_QUICK=1: 1024 particles, 0.1 s, 128^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, study_commit, auto_camera, frame_scene, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
PARTICLES=${PARTICLES:-$(quick 8192 1024)}
T_SIM=${T_SIM:-$(quick 0.5 0.1)}
OUT=$RESULTS/inacio2010
TMP=out/$(quick "" quick/)inacio2010/fig7
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "fig7.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
{
  printf '# %s; simulate dam_break --particles %s --eos ideal --sound-speed 15 --cpu; t = %s s; renders: volume_raycast, own appearance, %sx%s\n' \
    "$(study_commit)" "$PARTICLES" "$T_SIM" "$SIZE" "$SIZE"
  echo "steps_x_dt,frames,particles,clamps_total,v_max_peak,top_y"
} > "$TMP/fig7.csv"
for cfg in "1 0.01" "10 0.001"; do
  set -- $cfg
  frames=$(awk -v t="$T_SIM" -v s="$1" -v d="$2" 'BEGIN {printf "%d", t / (s * d) + 0.5}')
  mkdir -p "$TMP/s$1"
  "$BIN" simulate dam_break --particles "$PARTICLES" --eos ideal --sound-speed 15 --dt "$2" --substeps "$1" \
      --frames "$frames" --cpu -q -o "$TMP/s$1/frame_%04d.bgeo" --stats "$TMP/s$1/stats.csv"
  last=$(printf "$TMP/s$1/frame_%04d.bgeo" "$frames")
  # the stats' clamps column is the running total (fs_sph_stats.clamps): the last frame's is the count
  stats=$(awk -F, '$1 ~ /^[0-9]+$/ && $1 > 0 { c = $10; if ($9 > v) v = $9; n = $3 } END { print n "," c "," v }' "$TMP/s$1/stats.csv")
  top=$("$BIN" info "$last" 2> /dev/null | awk '/^bbox max:/ { print $4 }')
  echo "${1}x$2,$frames,$stats,$top" >> "$TMP/fig7.csv"
done
pat10=$TMP/s10/frame_%04d.bgeo
f10=$(awk -v t="$T_SIM" 'BEGIN {printf "%d", t / 0.01 + 0.5}')
frame_scene "$pat10" "$f10" "$SIZE" > "$TMP/cam.json"
auto_camera "$BIN" "$TMP/cam.json" "$TMP"
for s in 1 10; do
  frame_scene "$TMP/s$s/frame_%04d.bgeo" "$f10" "$SIZE" "$P_CAMERA" > "$TMP/s$s.json"
  "$BIN" render "$TMP/s$s.json" --method volume_raycast --appearance own -q -o "$TMP/s$s.png"
done
mv "$TMP/fig7.csv" "$OUT/fig7.csv"
frames_mosaic "$OUT/fig7_pair.png" 2x1 "$(quick 400x400 64x64)" "$TMP/s1.png" "$TMP/s10.png"
echo "wrote $OUT/fig7.csv, $OUT/fig7_pair.png"
