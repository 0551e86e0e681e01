#!/usr/bin/env bash
# When the reference's fine interior bits pay (methods/reference/README.md, `interior`):
# the interior and march stages (--timings, medians of RUNS) with reference.interior=on
# and off, thickness on, at square sizes from 256 to 1024 px, on three frames; and the
# size from which interior=auto builds the bits (its estimate W H cbrt(n) / n of rays per
# interior cell reaching FS_REF_VISITS in reference.c), scanned in steps of 16 px. Where
# on and off cost the same, the estimate is FS_REF_VISITS (S_even / S_auto)^2, which the
# rule's constant should be.
#
#   experiments/bench/interior_auto.sh          writes results/bench/interior_auto.csv
#   experiments/bench/interior_auto.sh --quick  (or FS_QUICK=1) 128 and 192 px, 1 run, the
#                                               bundled frames, into out/quick/results/bench/
#
# Frames as experiments/bench/thickness_counts.sh. Environment: BIN, RUNS, SHARED.
# Rows: frame,particles,size,variant,runs,interior_ms,march_ms,stages_ms,built (variant
# on/off: medians; variant auto: one render each, built 0|1 says whether it built the bits).
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; fi
source experiments/lib.sh # quick, RESULTS, STUDY_PROV, stamp_csv, median
BIN=${BIN:-./build/fluidsurf}
RUNS=${RUNS:-$(quick 3 1)}
SIZES=$(quick "256 384 512 640 768 1024" "128 192")
SCAN=$(quick "$(seq -s ' ' 128 16 1024)" "128 192")
SHARED=${SHARED:-../shared/data}
OUT=$RESULTS/bench
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"

reference_frames

# stages INPUT SIZE VARIANT: "interior_ms march_ms" of one render
stages() {
  # shellcheck disable=SC2086 # the input is a word list
  "$BIN" render $1 -W "$2" -H "$2" --method reference --set reference.interior="$3" --timings -q -o "$T/img.png" |
    awk -F, '$1 == "interior" {i = $2} $1 == "march" {m = $2} END {printf "%.1f %.1f\n", i, m}'
}

echo "frame,particles,size,variant,runs,interior_ms,march_ms,stages_ms,built" > "$T/rows"
for f in "${frames[@]}"; do
  IFS='|' read -r name file input <<< "$f"
  n=$("$BIN" info "$file" 2> /dev/null | sed -n 's/^particles: *\([0-9]*\).*/\1/p')
  for s in $SIZES; do
    for v in on off; do
      : > "$T/i"; : > "$T/m"
      for _ in $(seq "$RUNS"); do read -r i m < <(stages "$input" "$s" "$v"); echo "$i" >> "$T/i"; echo "$m" >> "$T/m"; done
      i=$(median < "$T/i"); m=$(median < "$T/m")
      echo "$name,$n,$s,$v,$RUNS,$i,$m,$(awk -v a="$i" -v b="$m" 'BEGIN {printf "%.1f", a + b}'),$([ "$v" = on ] && echo 1 || echo 0)" >> "$T/rows"
      echo "interior_auto: $name $s $v: $i + $m ms" >&2
    done
  done
  for s in $SCAN; do # the smallest size at which auto builds the bits
    read -r i m < <(stages "$input" "$s" auto)
    built=$(awk -v i="$i" 'BEGIN {print (i > 0) ? 1 : 0}')
    echo "$name,$n,$s,auto,1,$i,$m,$(awk -v a="$i" -v b="$m" 'BEGIN {printf "%.1f", a + b}'),$built" >> "$T/rows"
    [ "$built" = 1 ] && break
  done
done
{ echo "# $STUDY_PROV; tool=experiments/bench/interior_auto.sh; runs=$RUNS; load=$(cut -d' ' -f1-3 /proc/loadavg)"; cat "$T/rows"; } > "$OUT/interior_auto.csv"
echo "interior_auto: wrote $OUT/interior_auto.csv" >&2
