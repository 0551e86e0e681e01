#!/usr/bin/env bash
# inacio2010 volume_raycast: the issue's bar and the stage times.
#  1. Bar: coverage IoU (and depth, normal) of volume_raycast against `reference`
#     (same kernel and iso) on the 24k dam break, grid 256 (the default), SIZE^2,
#     both transfer functions (the G-buffer is the same; the own images differ).
#  2. Stage times (Tables I/II analogue, rendering side only) on synthetic boxes
#     of 1024, 2048, 4096, 8192 particles and 46^3 = 97,336: volume generation
#     layered vs slice vs exact (medians of VRUNS runs, default 5, at 64^2: the
#     volume does not depend on the image), ray casting with the layered volume
#     (faces + march; with and without the thickness march) vs `spheres`, at
#     SIZE^2 (medians of RUNS); each after a warm-up (fluidsurf compare --repeat). The grid spacing is the same for
#     every count, SPACING_R x r (default 0.5 r, about the dam break's spacing at
#     256): the paper keeps its volume resolution and kernel fixed while the
#     particle count grows in the same container, so the cost per particle is
#     fixed too. (A fixed 256 points across boxes of growing size would instead
#     give the 1k box 50 layers per particle and the 97k box 16.)
# Writes results/inacio2010/volume_raycast_{bar.csv,times.csv,*.png}. Every time
# names its renderer (llvmpipe here: CPU cores, not a GPU).
# FS_QUICK=1 (run_all.sh --quick): 128^2, 1 run, bar grid 64, the 1024 and 2048 boxes at
# spacing 1 r, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
RUNS=${RUNS:-$(quick 3 1)}
VRUNS=${VRUNS:-$(quick 5 1)}
GRID=${GRID:-$(quick 256 64)}
SPACING_R=${SPACING_R:-$(quick 0.5 1)}
BOXES=$(quick "16,8,8 16,16,8 16,16,16 32,16,16 46,46,46" "16,8,8 16,16,8")
R=$RESULTS/inacio2010
mkdir -p "$R"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One row per particle count from times.csv: the volume stage of the three builds
# (from the small-image runs), the slice/layered time ratio, ray casting (faces +
# march) with and without the thickness march, spheres (splat; splat + thickness),
# and the frame totals without thickness.
summarize() {
  awk -F, '!/^#/ && $1 != "particles" {
      n = $1; if (!(n in seen)) { seen[n] = 1; order[++k] = n; res[n] = $2 }
      t[n SUBSEP $3 SUBSEP $4 SUBSEP $5] = $6; r = $7; for (i = 8; i <= NF; i++) r = r "," $i }
    function g(n, m, v, st) { return t[n SUBSEP m SUBSEP v SUBSEP st] + 0 }
    END {
      print "# medians (ms) from volume_raycast_times.csv; renderer " r "; grid_res = points along the longest axis"
      print "particles,grid_res,volume_layered,volume_slice,volume_exact,slice_over_layered,raycast_no_thickness,raycast_with_thickness,spheres_splat,spheres_splat_thickness,volume_raycast_total_no_thickness,spheres_total_no_thickness"
      for (i = 1; i <= k; i++) {
        n = order[i]; m = "volume_raycast"
        vl = g(n, m, "build=layered", "volume"); vs = g(n, m, "build=slice", "volume"); ve = g(n, m, "build=exact", "volume")
        rc0 = g(n, m, "thickness=off", "faces") + g(n, m, "thickness=off", "march")
        rc1 = g(n, m, "thickness=on", "faces") + g(n, m, "thickness=on", "march")
        sp0 = g(n, "spheres", "thickness=off", "splat")
        sp1 = sp0 + g(n, "spheres", "thickness=on", "thickness")
        printf "%s,%s,%.1f,%.1f,%.1f,%.2f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f\n", n, res[n], vl, vs, ve, vs / vl, rc0, rc1, sp0, sp1,
          g(n, m, "thickness=off", "total"), g(n, "spheres", "thickness=off", "total")
      }
    }' "$1"
}

# 1. the bar (SKIP_BAR=1 leaves its files as they are)
if [ "${SKIP_BAR:-0}" != 1 ]; then
"$BIN" compare --no-cache experiments/scenes/dam_break.json --methods volume_raycast \
  --set volume_raycast.grid_res="$GRID" --set volume_raycast.mode=surface,translucent \
  -W "$SIZE" -H "$SIZE" --repeat "$RUNS" -q -o "$tmp/dam"
{ echo "# volume_raycast vs reference, experiments/scenes/dam_break.json (24389 particles), ${SIZE}x${SIZE}, grid $GRID; fluidsurf compare metrics.csv"
  grep -v '^#' "$tmp/dam/metrics.csv"; } > "$R/volume_raycast_bar.csv"
cp "$tmp/dam/volume_raycast_mode-surface.png" "$R/volume_raycast_dam_shared.png"
cp "$tmp/dam/volume_raycast_mode-surface_own.png" "$R/volume_raycast_dam_own_surface.png"
cp "$tmp/dam/volume_raycast_mode-translucent_own.png" "$R/volume_raycast_dam_own_translucent.png"
cp "$tmp/dam/reference.png" "$R/volume_raycast_dam_reference.png"
cp "$tmp/dam/panel.png" "$R/volume_raycast_dam_panel.png"
cp "$tmp/dam/diff_volume_raycast_mode-surface.png" "$R/volume_raycast_dam_diff.png"
fi

# 2. stage times on synthetic boxes
csv=$R/volume_raycast_times.csv
echo "# volume_raycast (grid spacing $SPACING_R r, step 0.5 spacing) and spheres on synthetic boxes (lattice 2r, r = 0.025, jitter 0.1 r); volume stage: medians of $VRUNS runs at 64x64 (variants build=...), the rest medians of $RUNS runs at ${SIZE}x${SIZE} (variants thickness=...), each after a warm-up; stages from fluidsurf compare timings.csv; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)" > "$csv.tmp"
echo "particles,grid_res,method,variant,stage,ms_median,renderer" >> "$csv.tmp"
for size in $BOXES; do
  IFS=, read -r a b c <<< "$size"
  n=$((a * b * c))
  # points along the longest axis: centres span (a - 1) 2r, the grid adds H = 4r each side
  res=$(awk -v a="$a" -v s="$SPACING_R" 'BEGIN { e = (a - 1) * 2 + 8; r = e / s; print (r == int(r) ? r : int(r) + 1) + 1 }')
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
  # volume generation alone (its time does not depend on the image): 64x64, VRUNS runs
  "$BIN" compare --no-cache "$tmp/box_$n.json" --methods volume_raycast \
    --set volume_raycast.grid_res="$res" --set volume_raycast.build=layered,slice,exact --set volume_raycast.thickness=off \
    -W 64 -H 64 --repeat "$VRUNS" -q -o "$tmp/vol_$n"
  # ray casting (layered volume) against spheres at SIZE^2
  "$BIN" compare --no-cache "$tmp/box_$n.json" --methods volume_raycast,spheres \
    --set volume_raycast.grid_res="$res" --set volume_raycast.thickness=on,off --set spheres.thickness=on,off \
    -W "$SIZE" -H "$SIZE" --repeat "$RUNS" -q -o "$tmp/box_$n"
  # timings.csv: method,variant,stage,ms_median,ms_min,ms_max,runs,gpu_ms_median,renderer
  for d in vol_$n box_$n; do
    awk -F, -v n="$n" -v g="$res" -v d="$d" '!/^#/ && $1 != "method" && $1 != "reference" {
        if (d ~ /^vol/) { if ($3 != "volume") next; sub(/;thickness=off/, "", $2) }
        r = $9; for (i = 10; i <= NF; i++) r = r "," $i;
        print n "," g "," $1 "," $2 "," $3 "," $4 "," r }' "$tmp/$d/timings.csv" >> "$csv.tmp"
  done
  [ "$n" = 8192 ] && cp "$tmp/box_$n/panel.png" "$R/volume_raycast_box_8192_panel.png"
done
publish "$csv"
summarize "$csv" > "$R/volume_raycast_summary.csv"
stamp_csv "$csv" "$R/volume_raycast_summary.csv" "$R/volume_raycast_bar.csv"
column -t -s, "$R/volume_raycast_bar.csv" | cut -c1-200
column -t -s, "$R/volume_raycast_summary.csv"
