#!/usr/bin/env bash
# xiao2017 Fig. 3 analogue: basic vs PCA vs blend normals, normal filter on/off.
#  - jittered slab and box (default jitter 0.1 r) at 512x512 against `analytic`:
#    the harness's metrics, plus the normal error split by where the ideal surface
#    point lies (experiments/tools/edge_bands.c): faces at least 2r from every ideal
#    edge, the slab's top face alone, the band within 2r of an ideal edge, and a
#    profile against the distance to the edge;
#  - the dam break at 512x512 against `reference` (the same field).
# Writes results/xiao2017/fig3_{slab,box,dam}_metrics.csv, fig3_{slab,box}_bands.csv,
# small panels fig3_*_panel.png and error maps fig3_*_errmap_*.png.
# Full outputs (EXR, full-size panels) stay in out/xiao2017/fig3/.
# FS_QUICK=1 (experiments/lib.sh): 128^2, into out/quick/results/xiao2017 and out/quick/xiao2017/fig3.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/edge_bands}
SIZE=${SIZE:-$(quick 512 128)}
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/fig3
mkdir -p "$OUT" "$TMP"
for x in "$BIN" "$TOOL"; do
  [ -x "$x" ] || { echo "fig3.sh: $x missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
done
SWEEP=(--methods raycast_pca --set raycast_pca.normals=basic,pca,blend --set raycast_pca.normal_filter=on,off)
small() { oiiotool "$1" --resize "$2" -o "$3"; } # downscaled copy for the repository

for shape in slab box; do
  d=$TMP/$shape
  "$BIN" compare --force --no-cache "experiments/scenes/$shape.json" "${SWEEP[@]}" --reference analytic -W "$SIZE" -H "$SIZE" \
      --repeat 1 -o "$d" 2> "$TMP/$shape.log"
  cp "$d/metrics.csv" "$OUT/fig3_${shape}_metrics.csv"
  exrs=()
  for n in basic pca blend; do for f in on off; do exrs+=("$d/raycast_pca_normals-${n}_normal_filter-$f.exr"); done; done
  "$TOOL" --profile "experiments/scenes/$shape.json" "$d/analytic.exr" "${exrs[@]}" |
      sed "/^#/!{s|$d/raycast_pca_normals-||; s|_normal_filter-|,filter=|; s|\.exr,|,|}; s|^file,region|normals,filter,region|" \
      > "$OUT/fig3_${shape}_bands.csv"
  stamp_csv "$OUT/fig3_${shape}_metrics.csv" "$OUT/fig3_${shape}_bands.csv"
  for n in basic blend; do
    "$TOOL" --map "$TMP/${shape}_errmap_$n.png" "experiments/scenes/$shape.json" "$d/analytic.exr" \
        "$d/raycast_pca_normals-${n}_normal_filter-on.exr" > /dev/null
    small "$TMP/${shape}_errmap_$n.png" "$(quick 256x256 128x128)" "$OUT/fig3_${shape}_errmap_$n.png"
  done
  small "$d/panel.png" "$(quick 640x0 320x0)" "$OUT/fig3_${shape}_panel.png"
  echo "fig3: $shape done"
done

d=$TMP/dam
"$BIN" compare --force --no-cache experiments/scenes/dam_break.json "${SWEEP[@]}" -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" 2> "$TMP/dam.log"
cp "$d/metrics.csv" "$OUT/fig3_dam_metrics.csv"
stamp_csv "$OUT/fig3_dam_metrics.csv"
small "$d/panel.png" "$(quick 640x0 320x0)" "$OUT/fig3_dam_panel.png"
echo "fig3: dam break done; wrote $OUT/fig3_*"
