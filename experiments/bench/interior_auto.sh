#!/usr/bin/env bash
# When the reference's fine interior proofs pay, and what proving them on demand saves
# (methods/reference/README.md, `interior`). On every frame of the reference studies
# (reference_frames: the DualSPHysics frame auto-framed and from above, splash, dam_break), at
# square sizes from 256 to 2048 px, thickness on, with reference.interior=off (no proofs), on
# (every cell's proof up front) and demand (a cell's proof when a ray first enters it inside):
# the interior and march stages (--timings, medians of RUNS; proofs on demand are made, and
# timed, in the march) and the work counts of one counting render: the proofs made, the sums
# of the first-hit march, of the thickness march and of its unproven interior. Then the size
# from which interior=auto makes proofs (the estimate of reference.c's want_interior), scanned
# in steps of 16 px.
#
#   experiments/bench/interior_auto.sh          writes results/bench/interior_auto.csv
#   experiments/bench/interior_auto.sh --quick  (or FS_QUICK=1) 128 and 192 px, 1 run, the
#                                               bundled frames, into out/quick/results/bench/
#
# Environment: BIN, RUNS, SHARED, SIZES, FRAMES (only these frames: their rows replace theirs
# in the CSV when it was made at the same commit, so the study can be run in parts).
# Rows: frame,particles,size,variant,runs,interior_ms,march_ms,stages_ms,built,proofs,
# march_evals,thickness_evals,inside_evals (variant on/off/demand: medians and one counting
# render; auto: one render each, built 0|1 says whether it made proofs, no counts).
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; fi
source experiments/lib.sh # quick, RESULTS, STUDY_PROV, median, reference_frames
BIN=${BIN:-./build/fluidsurf}
RUNS=${RUNS:-$(quick 3 1)}
SIZES=${SIZES:-$(quick "256 384 512 768 1024 1536 2048" "128 192")}
SCAN=$(quick "$(seq -s ' ' 128 16 2048)" "128 192")
SHARED=${SHARED:-../shared/data}
OUT=$RESULTS/bench
CSV=$OUT/interior_auto.csv
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"
reference_frames "$BIN" "$T"
HEADER="frame,particles,size,variant,runs,interior_ms,march_ms,stages_ms,built,proofs,march_evals,thickness_evals,inside_evals"

# stages INPUT SIZE VARIANT: "interior_ms march_ms" of one timed render
stages() {
  # shellcheck disable=SC2086 # the input is a word list
  "$BIN" render $1 -W "$2" -H "$2" --method reference --set reference.interior="$3" --timings -q -o "$T/img.png" |
    awk -F, '$1 == "interior" {i = $2} $1 == "march" {m = $2} END {printf "%.1f %.1f\n", i, m}'
}
# counts INPUT SIZE VARIANT: "proofs march_evals thickness_evals inside_evals" of one counting render
counts() {
  # shellcheck disable=SC2086 # the input is a word list
  "$BIN" render $1 -W "$2" -H "$2" --method reference --set reference.interior="$3" --counters -q -o "$T/img.png" |
    awk -F, '$4 == "interior" && $5 == "field_evals" {p = $6 / 512} $4 == "march" && $5 == "field_evals" {m = $6}
      $4 == "thickness" && $5 == "field_evals" {t = $6} $4 == "thickness" && $5 == "inside_evals" {n = $6}
      END {printf "%d %d %d %d\n", p, m, t, n}'
}

# one_frame NAME INPUT N: the frame's rows
one_frame() {
  local name=$1 input=$2 n=$3 s v i m p me te ie
  for s in $SIZES; do
    for v in off on demand; do
      : > "$T/i"; : > "$T/m"
      for _ in $(seq "$RUNS"); do read -r i m < <(stages "$input" "$s" "$v"); echo "$i" >> "$T/i"; echo "$m" >> "$T/m"; done
      i=$(median < "$T/i"); m=$(median < "$T/m")
      read -r p me te ie < <(counts "$input" "$s" "$v")
      echo "$name,$n,$s,$v,$RUNS,$i,$m,$(awk -v a="$i" -v b="$m" 'BEGIN {printf "%.1f", a + b}'),$((p > 0)),$p,$me,$te,$ie"
      echo "interior_auto: $name $s $v: $i + $m ms, $p proofs" >&2
    done
  done
  for s in $SCAN; do # the smallest size at which auto makes proofs
    read -r i m < <(stages "$input" "$s" auto)
    read -r p me te ie < <(counts "$input" "$s" auto)
    echo "$name,$n,$s,auto,1,$i,$m,$(awk -v a="$i" -v b="$m" 'BEGIN {printf "%.1f", a + b}'),$((p > 0)),,,,"
    if [ "$p" -gt 0 ]; then break; fi # auto may make none at every scanned size
  done
}

in_list() { local x=$1; shift; for y in "$@"; do [ "$x" = "$y" ] && return 0; done; return 1; }
: > "$T/rows"
# a part of the study: keep the other frames' rows of a CSV made at this commit
if [ -n "${FRAMES:-}" ] && [ -s "$CSV" ] && head -1 "$CSV" | grep -qF "# $STUDY_PROV;"; then
  # shellcheck disable=SC2086 # FRAMES is a word list
  awk -F, -v keep=" $FRAMES " '!/^#/ && $1 != "frame" && index(keep, " " $1 " ") == 0' "$CSV" > "$T/rows"
fi
for f in "${frames[@]}"; do
  IFS='|' read -r name file input <<< "$f"
  # shellcheck disable=SC2086 # FRAMES is a word list
  [ -z "${FRAMES:-}" ] || in_list "$name" $FRAMES || continue
  n=$("$BIN" info "$file" 2> /dev/null | sed -n 's/^particles: *\([0-9]*\).*/\1/p')
  one_frame "$name" "$input" "$n" >> "$T/rows"
done
{ echo "# $STUDY_PROV; tool=experiments/bench/interior_auto.sh; runs=$RUNS; load=$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "$HEADER"; sort -t, -k1,1 -s "$T/rows"; } > "$T/out.csv"
mv "$T/out.csv" "$CSV"
echo "interior_auto: wrote $CSV" >&2
