#!/usr/bin/env bash
# Makes the splashing frame of the speed benchmark (issue 13): fluidsurf's own
# SPH simulator (fluidsurf simulate, CPU path, Tait) runs its dam_break scene
# with about 100k fluid particles at r = 0.025 (the tank grows with the count:
# a 2.29 m column of water at one end of a 5.5 m tank) and keeps the frame at
# t = FRAMES / FPS seconds, after the front has hit the far wall and the jet has
# thrown spray up and back over the tank.
#
#   experiments/bench/make_splash.sh [OUT.ply]   (default experiments/data/splash/dam_break_splash_100k.ply)
#
# There is no random seed: the fluid starts on a lattice, and the CPU path's
# loops are per particle (their reductions are max and integer sums), so the
# result does not depend on the thread count. Takes 15-30 minutes on 2 shared
# cores (about 0.14 s per step for 168k particles with the boundary, ~3,500 steps
# per simulated second). Writes the frame's stats CSV beside it.
# FS_QUICK=1 (run_all.sh --quick): about 3,000 particles, 2 frames (t = 0.2 s), into
# out/quick/results/bench/make_splash/dam_break_splash.ply (the committed frame is not touched).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # quick, RESULTS
OUT=${1:-$(quick experiments/data/splash/dam_break_splash_100k.ply "$RESULTS/bench/make_splash/dam_break_splash.ply")}
BIN=${BIN:-./build/fluidsurf}
PARTICLES=${PARTICLES:-$(quick 100000 3000)}
FPS=${FPS:-10}
FRAMES=${FRAMES:-$(quick 10 2)}
[ -x "$BIN" ] || bash scripts/build.sh "$(dirname "$BIN")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$(dirname "$OUT")"
echo "make_splash: simulating dam_break, $PARTICLES particles, $FRAMES frames at $FPS fps (t = $(awk -v f="$FRAMES" -v p="$FPS" 'BEGIN {print f / p}') s)" >&2
start=$(date +%s)
"$BIN" simulate dam_break --cpu --particles "$PARTICLES" --fps "$FPS" --frames "$FRAMES" \
  --stats "$tmp/stats.csv" -o "$tmp/f_%04d.ply"
last=$(printf '%s/f_%04d.ply' "$tmp" "$FRAMES")
cp "$last" "$OUT"
cp "$tmp/stats.csv" "${OUT%.ply}.stats.csv"
echo "make_splash: wrote $OUT ($("$BIN" info "$OUT" | sed -n 's/^particles: //p') particles) in $(($(date +%s) - start)) s" >&2
