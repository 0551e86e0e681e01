#!/usr/bin/env bash
# iwasaki2006 section 6 analogue: surfel counts, extraction time and frame time
# at SIZE^2 (default 512) with and without caustics, on the 24k dam break and
# the double dam break; the own-appearance images (reflection, refraction,
# caustics) and a panel beside `reference` (same kernel and iso), with the
# coverage IoU. Medians of RUNS (default 3) timed runs after a warm-up.
# Writes results/iwasaki2006/{surfels.csv, <scene>_*.png, <scene>_metrics.csv}.
# FS_QUICK=1 (run_all.sh --quick): 128^2, 1 run, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
RUNS=${RUNS:-$(quick 3 1)}
R=$RESULTS/iwasaki2006
mkdir -p "$R"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
csv=$R/surfels.csv
echo "# surfels (iwasaki2006 defaults) at ${SIZE}x${SIZE}; medians of $RUNS runs; stages from fluidsurf compare" > "$csv.tmp"
echo "scene,particles,surfels,caustics,stage,ms_median,renderer" >> "$csv.tmp"
for scene in dam_break:experiments/scenes/dam_break.json double_dam:experiments/xu2022/double_dam_break.json; do
  name=${scene%%:*} json=${scene#*:}
  "$BIN" compare --no-cache "$json" --methods surfels --set surfels.caustics=on,off -W "$SIZE" -H "$SIZE" --repeat "$RUNS" -q -o "$tmp/$name"
  "$BIN" render "$json" --method surfels -q $(quick "" "-W $SIZE -H $SIZE") --export "$tmp/$name.ply"
  surfels=$(grep -a -m1 '^element vertex' "$tmp/$name.ply" | awk '{print $3}')
  particles=$("$BIN" info "$(awk -F'"' '/"particles"/ {print $4}' "$json" | sed "s|^|$(dirname "$json")/|")" | awk '/^particles:/ {print $2}')
  # timings.csv: method,variant,stage,ms_median,ms_min,ms_max,runs,gpu_ms_median,renderer
  awk -F, -v s="$name" -v n="$particles" -v k="$surfels" '!/^#/ && $1 == "surfels" {
      split($2, v, "="); c = v[2]; r = $9; for (i = 10; i <= NF; i++) r = r "," $i;
      print s "," n "," k "," c "," $3 "," $4 "," r }' "$tmp/$name/timings.csv" >> "$csv.tmp"
  cp "$tmp/$name/metrics.csv" "$R/${name}_metrics.csv"
  cp "$tmp/$name/surfels_caustics-on_own.png" "$R/${name}_own.png"
  cp "$tmp/$name/surfels_caustics-on.png" "$R/${name}_shared.png"
  cp "$tmp/$name/reference.png" "$R/${name}_reference.png"
  cp "$tmp/$name/panel.png" "$R/${name}_panel.png"
  oiiotool "$tmp/$name/surfels_caustics-on.exr" --ch caustics --ch 0,0,0 -o "$R/${name}_caustics.png"
done
publish "$csv"
stamp_csv "$csv" "$R"/{dam_break,double_dam}_metrics.csv
column -t -s, "$csv"
