#!/usr/bin/env bash
# inacio2010 Fig. 2 analogue: spheres against the ray-cast surface on the same frame of
# 4096 particles. The dam break of fig9.sh (1 m column, 2.4 x 1.6 x 1.0 m tank, r =
# 0.5 / cbrt(N)) is simulated to 1.0 s with 4096 particles (CPU path, Tait), and
# `fluidsurf compare` renders that frame with spheres and volume_raycast (shipped
# defaults) against the exact reference, at SIZE^2 (default 512), the camera framing
# the fluid. Writes results/inacio2010/fig2_pair.png (spheres; volume_raycast, shared
# shading; volume_raycast, its own opaque surface) and fig2_metrics.csv, fig2_timings.csv
# (compare's: the renderer is named in each timing row). Work in out/inacio2010/fig2/.
# FS_QUICK=1: 512 particles, 0.1 s, 128^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
N=${N:-$(quick 4096 512)}
T_SIM=${T_SIM:-$(quick 1.0 0.1)}
SIZE=${SIZE:-$(quick 512 128)}
OUT=$RESULTS/inacio2010
TMP=out/$(quick "" quick/)inacio2010/fig2
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "fig2.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
r=$(awk -v n="$N" 'BEGIN { printf "%.6g", 0.5 / exp(log(n) / 3) }')
frame=$TMP/dam_0010.bgeo
[ -f "$frame" ] || "$BIN" simulate dam_break --particles "$N" --radius "$r" --fps "$(awk -v t="$T_SIM" 'BEGIN { print 10 / t }')" \
    --frames 10 --cpu -q -o "$TMP/dam_%04d.bgeo" --stats "$TMP/stats.csv"
printf '{"particles": "dam_0010.bgeo", "radius": %s, "up": "y", "material": "water", "background": "checker"}\n' "$r" \
    > "$TMP/scene.json"
"$BIN" compare --force --no-cache "$TMP/scene.json" --methods spheres,volume_raycast -W "$SIZE" -H "$SIZE" --repeat 3 \
    -o "$TMP/compare" -q 2> "$TMP/compare.log"
cp "$TMP/compare/metrics.csv" "$OUT/fig2_metrics.csv"
cp "$TMP/compare/timings.csv" "$OUT/fig2_timings.csv"
stamp_csv "$OUT/fig2_metrics.csv" "$OUT/fig2_timings.csv"
frames_mosaic "$OUT/fig2_pair.png" 3x1 "$(quick 400x400 64x64)" "$TMP/compare/spheres.png" \
    "$TMP/compare/volume_raycast.png" "$TMP/compare/volume_raycast_own.png"
echo "wrote $OUT/fig2_metrics.csv, $OUT/fig2_timings.csv, $OUT/fig2_pair.png"
