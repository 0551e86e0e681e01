#!/usr/bin/env bash
# inacio2010 volume_raycast: the issue's bar and the stage times.
#  1. Bar: coverage IoU (and depth, normal) of volume_raycast against `reference`
#     (same kernel and iso) on the 24k dam break, grid 256 (the default), SIZE^2,
#     both transfer functions (the G-buffer is the same; the own images differ).
#  2. Stage times (Tables I/II analogue, rendering side only) on synthetic boxes
#     of 1024, 2048, 4096, 8192 particles and 46^3 = 97,336: volume generation
#     layered vs slice vs exact, ray casting (faces + march; with and without the
#     thickness march) vs `spheres`, at SIZE^2, grid GRID; medians of RUNS timed
#     runs after a warm-up (fluidsurf compare --repeat).
# Writes results/inacio2010/volume_raycast_{bar.csv,times.csv,*.png}. Every time
# names its renderer (llvmpipe here: CPU cores, not a GPU).
set -euo pipefail
cd "$(dirname "$0")/../.."
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-512}
RUNS=${RUNS:-3}
GRID=${GRID:-256}
R=results/inacio2010
mkdir -p "$R"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. the bar
"$BIN" compare experiments/scenes/dam_break.json --methods volume_raycast \
  --set volume_raycast.grid_res="$GRID" --set volume_raycast.mode=surface,translucent \
  -W "$SIZE" -H "$SIZE" --repeat "$RUNS" -q -o "$tmp/dam"
{ echo "# volume_raycast vs reference, experiments/scenes/dam_break.json (24,389 particles), ${SIZE}x${SIZE}, grid $GRID; fluidsurf compare metrics.csv"
  grep -v '^#' "$tmp/dam/metrics.csv"; } > "$R/volume_raycast_bar.csv"
cp "$tmp/dam/volume_raycast_mode=surface.png" "$R/volume_raycast_dam_shared.png"
cp "$tmp/dam/volume_raycast_mode=surface_own.png" "$R/volume_raycast_dam_own_surface.png"
cp "$tmp/dam/volume_raycast_mode=translucent_own.png" "$R/volume_raycast_dam_own_translucent.png"
cp "$tmp/dam/reference.png" "$R/volume_raycast_dam_reference.png"
cp "$tmp/dam/panel.png" "$R/volume_raycast_dam_panel.png"
cp "$tmp/dam/diff_volume_raycast_mode=surface.png" "$R/volume_raycast_dam_diff.png"

# 2. stage times on synthetic boxes
csv=$R/volume_raycast_times.csv
echo "# volume_raycast (grid $GRID, step 0.5 spacing) and spheres at ${SIZE}x${SIZE} on synthetic boxes (lattice 2r, r = 0.025, jitter 0.1 r); medians of $RUNS runs after a warm-up; stages from fluidsurf compare timings.csv" > "$csv.new"
echo "particles,method,variant,stage,ms_median,renderer" >> "$csv.new"
for size in 16,8,8 16,16,8 16,16,16 32,16,16 46,46,46; do
  IFS=, read -r a b c <<< "$size"
  n=$((a * b * c))
  cat > "$tmp/box_$n.json" <<JSON
{
  "description": "synthetic box of $a x $b x $c = $n particles",
  "particles": {"synthetic": "box", "size": [$a, $b, $c], "jitter": 0.1, "seed": 1},
  "radius": 0.025,
  "material": "water",
  "background": "checker",
  "camera": {"width": $SIZE, "height": $SIZE}
}
JSON
  "$BIN" compare "$tmp/box_$n.json" --methods volume_raycast,spheres \
    --set volume_raycast.grid_res="$GRID" --set volume_raycast.build=layered,slice,exact \
    --set volume_raycast.thickness=on,off --set spheres.thickness=on,off \
    -W "$SIZE" -H "$SIZE" --repeat "$RUNS" -q -o "$tmp/box_$n"
  # timings.csv: method,variant,stage,ms_median,ms_min,ms_max,runs,renderer
  awk -F, -v n="$n" '!/^#/ && $1 != "method" && $1 != "reference" {
      r = $8; for (i = 9; i <= NF; i++) r = r "," $i;
      print n "," $1 "," $2 "," $3 "," $4 "," r }' "$tmp/box_$n/timings.csv" >> "$csv.new"
  [ "$n" = 8192 ] && cp "$tmp/box_$n/panel.png" "$R/volume_raycast_box_8192_panel.png"
done
mv "$csv.new" "$csv"
column -t -s, "$R/volume_raycast_bar.csv" | cut -c1-200
column -t -s, "$csv"
