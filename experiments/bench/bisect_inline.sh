#!/usr/bin/env bash
# Issue 50, part 4: the reference's bisection and crossing written once, as one static
# inline function (methods/reference/reference_bisect.h), must be no slower. Times the two
# paths that bisect, reference.accel=off (thickness on) and reference.field=zhu_bridson
# (thickness off: with it on, one render takes about 2.5 minutes on 2 cores), at SIZE x SIZE
# on the shared DualSPHysics frame, with the binaries of the commit before and
# the commit after, runs alternating, medians of RUNS: the whole process's wall time and the
# march stage (--timings).
#
#   experiments/bench/bisect_inline.sh BEFORE_BIN AFTER_BIN   writes results/bench/bisect_inline.csv
#
# Each binary's commit comes from its own EXR provenance. Environment: RUNS (3), SIZE (1024),
# SHARED (../shared/data). Run it on a quiet machine (`quiet`).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, RESULTS, exr_attr
[ $# = 2 ] || { echo "usage: $0 BEFORE_BIN AFTER_BIN" >&2; exit 2; }
RUNS=${RUNS:-3} SIZE=${SIZE:-1024} SHARED=${SHARED:-../shared/data}
DSPH=$SHARED/dualsphysics/dambreak200k_t0.300.vtk
[ -f "$DSPH" ] || { echo "bisect_inline.sh: $DSPH missing (set SHARED)" >&2; exit 2; }
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
bins=("$1" "$2") names=(before after) paths=(accel=off field=zhu_bridson,thickness=off)
for b in "${bins[@]}"; do [ -x "$b" ] || { echo "bisect_inline.sh: $b is not an executable" >&2; exit 2; }; done
for k in $(seq "$RUNS"); do
  for p in "${paths[@]}"; do
    for i in 0 1; do
      /usr/bin/time -f %e -o "$T/time" "${bins[$i]}" render "$DSPH" --up z --radius 0.00365 -W "$SIZE" -H "$SIZE" \
        --method reference $(tr , '\n' <<< "$p" | sed 's/^/--set reference./' | tr '\n' ' ') -q --timings -o "$T/${names[$i]}.exr" > "$T/stages"
      echo "$(cat "$T/time") $(awk -F, '$1 == "march" {print $2}' "$T/stages")" >> "$T/${names[$i]}.$p"
      echo "bisect_inline: run $k, $p, ${names[$i]}: $(tail -1 "$T/${names[$i]}.$p")" >&2
    done
  done
done
csv=$RESULTS/bench/bisect_inline.csv
{
  echo "# tool=experiments/bench/bisect_inline.sh; size=${SIZE}x$SIZE; runs=$RUNS; frame=$DSPH; load=$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "binary,commit,dirty,settings,runs,wall_s_median,march_ms_median,march_after_over_before"
  for p in "${paths[@]}"; do
    for i in 0 1; do
      n=${names[$i]}
      wall=$(awk '{print $1}' "$T/$n.$p" | median)
      march=$(awk '{print $2}' "$T/$n.$p" | median)
      [ "$i" = 0 ] && base=$march
      ratio=$([ "$i" = 1 ] && awk -v a="$march" -v b="$base" 'BEGIN {printf "%.3f", a / b}' || echo "")
      echo "$n,$(exr_attr "$T/$n.exr" commit),$(exr_attr "$T/$n.exr" dirty),${p//,/;},$RUNS,$wall,$march,$ratio"
    done
  done
} > "$T/out.csv"
mv "$T/out.csv" "$csv"
echo "bisect_inline: wrote $csv" >&2
