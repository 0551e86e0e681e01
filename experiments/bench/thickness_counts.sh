#!/usr/bin/env bash
# Why thickness costs what it does (issue 33, part 1): the reference's work counters on
# three frames (the DualSPHysics one also from above), with thickness off, on (interior proofs
# as `auto` decides), on with the proofs made on demand (interior=demand) and on without them
# (interior=off). One counting render each (`render --counters`, after
# its timed render; docs/DESIGN.md, "Work counters"), split at each ray's first hit: stage
# `march` is the first-hit march, `thickness` the march after it (methods/reference/README.md).
# The counts depend only on the particles, view, size and parameters, not on the machine.
#
#   experiments/bench/thickness_counts.sh          512x512; writes results/bench/thickness_counts.csv
#   experiments/bench/thickness_counts.sh --quick  (or FS_QUICK=1) 64x64, the two bundled frames,
#                                                  into out/quick/results/bench/
#
# Frames: dualsphysics, the 205k-particle DualSPHysics dam break just after impact
# ($SHARED/dualsphysics/dambreak200k_t0.300.vtk, z up, r = 0.00365 as its README gives;
# auto-framed, and dualsphysics_above: looking down z from as far, lib.sh's view_from_above); splash, fluidsurf's own 100k splash frame (experiments/data/splash, r in its
# header; auto-framed); dam_break, the bundled 24k frame 23 as experiments/scenes/dam_break.json
# frames it (r = 0.025, volume_scale 0.8). Environment: BIN (./build/fluidsurf), SIZE,
# SHARED (../shared/data).
#
# One row per frame, variant and stage (march, thickness, bounds, interior, total; bounds and
# interior made on demand by the march are stages of counts only) with every
# counter of the reference as a column; pixels and hits (first-hit crossings: covered pixels)
# repeated on each row, so per-ray and per-hit ratios need one lookup each.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; fi
source experiments/lib.sh # quick, RESULTS, STUDY_PROV, stamp_csv
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 64)}
SHARED=${SHARED:-../shared/data}
OUT=$RESULTS/bench
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"

# NAME|PARTICLE FILE|RENDER INPUT AND OPTIONS
reference_frames "$BIN" "$T"
# NAME|OPTIONS
variants=("thickness_off|--set reference.thickness=off" "thickness_on|"
          "thickness_on_demand|--set reference.interior=demand" "thickness_on_no_interior|--set reference.interior=off")
counters="field_evals neighbours_visited march_samples crossings cells_walked cells_marched cells_marched_inside"
counters="$counters cells_proven_inside cells_proven_outside refine_evals inside_evals"

csv=$T/thickness_counts.csv
: > "$T/prov"
echo "frame,particles,r,width,height,variant,stage,pixels,hits,$(tr ' ' ',' <<< "$counters")" > "$T/rows"
for f in "${frames[@]}"; do
  IFS='|' read -r name file input <<< "$f"
  n=$("$BIN" info "$file" 2> /dev/null | sed -n 's/^particles: *\([0-9]*\).*/\1/p')
  for v in "${variants[@]}"; do
    IFS='|' read -r variant opts <<< "$v"
    echo "thickness_counts: $name, $variant" >&2
    # shellcheck disable=SC2086 # input and opts are word lists
    "$BIN" render $input -W "$SIZE" -H "$SIZE" --method reference $opts -q --counters -o "$T/img.png" > "$T/out.txt"
    grep '^# ' "$T/out.txt" | head -1 | sed "s/^# /# $name, $variant: /" >> "$T/prov"
    r=$(grep -m1 '^# ' "$T/out.txt" | grep -o '; r=[^;]*' | cut -d= -f2)
    grep -v '^#' "$T/out.txt" | awk -F, -v name="$name" -v n="$n" -v r="$r" -v size="$SIZE" -v variant="$variant" \
      -v counters="$counters" '
      NR == 1 { next } # the header
      { if (!($4 in seen)) { seen[$4] = 1; order[++ns] = $4 } v[$4, $5] = $6 }
      END {
        nc = split(counters, c, " ")
        for (i = 1; i <= ns; i++) {
          s = order[i]
          line = name "," n "," r "," size "," size "," variant "," s "," size * size "," v["march", "crossings"] + 0
          for (k = 1; k <= nc; k++) line = line "," v[s, c[k]] + 0
          print line
        }
      }' >> "$T/rows"
  done
done
{ echo "# $STUDY_PROV; tool=experiments/bench/thickness_counts.sh; size=${SIZE}x$SIZE"; cat "$T/prov" "$T/rows"; } > "$csv"
stamp_csv "$csv"
cp "$csv" "$OUT/thickness_counts.csv"
echo "thickness_counts: wrote $OUT/thickness_counts.csv" >&2
