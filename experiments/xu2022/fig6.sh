#!/usr/bin/env bash
# xu2022 Figs. 4, 6, 7 analogue: aniso_ssf as a grid, rows anisotropy off / on,
# columns filter none / gaussian / bilateral / curvature / narrow (everything else
# at the shipped defaults: 2 iterations, curvature flow 80).
#  - dam break (24,389 particles) and double dam break (4,732, scene in this folder)
#    at SIZE^2 (default 512) against both exact references: the isotropic SPH
#    iso-surface (`reference`) and Yu & Turk's anisotropic one
#    (`reference:field=anisotropic`, the surface the ellipsoids approximate);
#  - jittered slab and box (default jitter 0.1 r) against `analytic`, plus the
#    interior error split into faces >= 2r from an ideal edge and the 2r edge band
#    (experiments/tools/edge_bands.c).
# Writes results/xu2022/fig6_<scene>_metrics.csv, fig6_{slab,box}_bands.csv and
# downscaled panels fig6_<scene>_panel.png / fig6_<scene>_grid.png.
# Full outputs (EXR, full-size panels) stay in out/xu2022/fig6/ (bars.sh reads them).
# FS_QUICK=1 (experiments/lib.sh): 128^2 (the grid crops scaled to it), into
# out/quick/results/xu2022 and out/quick/xu2022/fig6.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/edge_bands}
SIZE=${SIZE:-$(quick 512 128)}
OUT=$RESULTS/xu2022
TMP=out/$(quick "" quick/)xu2022/fig6
mkdir -p "$OUT" "$TMP"
for x in "$BIN" "$TOOL"; do
  [ -x "$x" ] || { echo "fig6.sh: $x missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
done
FILTERS="none gaussian bilateral curvature narrow"
SWEEP=(--methods aniso_ssf --set aniso_ssf.anisotropy=off,on --set "aniso_ssf.filter=${FILTERS// /,}")
small() { oiiotool "$1" --resize "$2" --ch R,G,B -o "$3"; }
# grid DIR OUTPNG REF CROP: the ten shaded images as a 5 x 2 grid (rows anisotropy
# off / on, columns none gaussian bilateral curvature narrow), the reference in front
# of each row; each image cropped to CROP (WxH+X+Y, SIZE=512 pixels) and shrunk to 150 px.
# Quick mode scales CROP to SIZE.
grid() {
  local d=$1 out=$2 ref=$3 crop=$4 args=()
  if [ "$FS_QUICK" = 1 ]; then
    crop=$(echo "$crop" | awk -F'[x+]' -v s="$SIZE" '{f = s / 512; printf "%dx%d+%d+%d", $1 * f, $2 * f, $3 * f, $4 * f}')
  fi
  for a in off on; do
    args+=("$d/$ref.png" --cut "$crop" --resize $(quick 150x150 64x64))
    for f in $FILTERS; do args+=("$d/aniso_ssf_anisotropy-${a}_filter-$f.png" --cut "$crop" --resize $(quick 150x150 64x64)); done
  done
  oiiotool "${args[@]}" --mosaic 6x2 --ch R,G,B -o "$out"
}

for spec in "dam:experiments/scenes/dam_break.json:400x400+50+30" "double_dam:experiments/xu2022/double_dam_break.json:400x400+56+100"; do
  IFS=: read -r label scene crop <<< "$spec"
  d=$TMP/$label
  "$BIN" compare --force --no-cache "$scene" "${SWEEP[@]}" --reference reference --reference reference:field=anisotropic \
      -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" -q 2> "$TMP/$label.log"
  cp "$d/metrics.csv" "$OUT/fig6_${label}_metrics.csv"
  stamp_csv "$OUT/fig6_${label}_metrics.csv"
  small "$d/panel.png" "$(quick 640x0 320x0)" "$OUT/fig6_${label}_panel.png"
  grid "$d" "$OUT/fig6_${label}_grid.png" reference "$crop"
  echo "fig6: $label done"
done

for spec in slab:440x300+30+150 box:460x460+26+10; do
  IFS=: read -r shape crop <<< "$spec"
  d=$TMP/$shape
  "$BIN" compare --force --no-cache "experiments/scenes/$shape.json" "${SWEEP[@]}" --reference analytic \
      -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" -q 2> "$TMP/$shape.log"
  cp "$d/metrics.csv" "$OUT/fig6_${shape}_metrics.csv"
  exrs=()
  for a in off on; do for f in $FILTERS; do exrs+=("$d/aniso_ssf_anisotropy-${a}_filter-$f.exr"); done; done
  "$TOOL" "experiments/scenes/$shape.json" "$d/analytic.exr" "${exrs[@]}" |
      sed "/^#/!{s|$d/aniso_ssf_anisotropy-||; s|_filter-|,|; s|\.exr,|,|}; s|^file,region|anisotropy,filter,region|" \
      > "$OUT/fig6_${shape}_bands.csv"
  stamp_csv "$OUT/fig6_${shape}_metrics.csv" "$OUT/fig6_${shape}_bands.csv"
  small "$d/panel.png" "$(quick 640x0 320x0)" "$OUT/fig6_${shape}_panel.png"
  grid "$d" "$OUT/fig6_${shape}_grid.png" analytic "$crop"
  echo "fig6: $shape done"
done
echo "wrote $OUT/fig6_*"
