#!/usr/bin/env bash
# raycast_pca's thickness (xiao2017 3.4: additive sphere splatting) against the exact
# thickness of `reference` (the path length inside the iso-surface) on the three frames
# the xiao2017 studies and the reference's studies use: the dam break (dam_break.json),
# the synthetic box (box.json) and fluidsurf's 100k splash frame (experiments/data/splash).
# Per frame and variant, over the pixels both cover (experiments/tools/thickness_error.c):
# the mean thicknesses, the ratio of their means, the mean and median of the per-pixel
# ratio, and the mean and p95 of |raycast_pca - reference| in multiples of r. Variants:
# thick_weight=chord at 1 r (the bare chord sum: the method before issue 35), and
# thick_weight=volume (each sphere's chord times V / its volume) at sphere radii RADII;
# the default is picked from these rows (methods/raycast_pca/README.md).
# Writes results/xiao2017/thickness.csv and thickness_heatmap.png (rows: the bare chord at
# 1 r, the shipped default; columns: dam break, box, splash; red thicker than the
# reference, blue thinner, full colour at 4 r; grey: only one covers). Work in
# out/xiao2017/thickness/. FS_QUICK=1 (experiments/lib.sh): 64^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, STUDY_PROV, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/thickness_error}
SIZE=${SIZE:-$(quick 256 64)}
RADII=${RADII:-$(quick "1 1.5 2 2.5 3 4" "1 2.5")}
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/thickness
mkdir -p "$OUT" "$TMP"
for x in "$BIN" "$TOOL"; do
  [ -x "$x" ] || { echo "thickness.sh: $x missing: cmake --build build" >&2; exit 2; }
done
frames=("dam_break|experiments/scenes/dam_break.json" "box|experiments/scenes/box.json"
        "splash|experiments/data/splash/dam_break_splash_100k.ply")
# the shipped defaults, as `fluidsurf methods raycast_pca` prints them
default() { "$BIN" methods raycast_pca | awk -v p="$1" '$1 == p && $2 == "=" { print $3 }'; }
def_radius=$(default thick_radius) def_weight=$(default thick_weight)
[ -n "$def_radius" ] && [ -n "$def_weight" ] || { echo "thickness.sh: no thickness defaults in 'fluidsurf methods raycast_pca'" >&2; exit 2; }
render() { nice -n 19 "$BIN" render "$1" -W "$SIZE" -H "$SIZE" -q "${@:2}"; }
{
  echo "# $STUDY_PROV; size=${SIZE}x${SIZE}; raycast_pca thickness against reference's over pixels both cover (thickness_error); default: thick_weight=$def_weight thick_radius=$def_radius"
  echo "frame,weight,radius_r,default,$("$TOOL" --header | cut -d, -f2-)"
} > "$TMP/thickness.csv"
maps_old=() maps_new=()
for spec in "${frames[@]}"; do
  name=${spec%%|*} input=${spec#*|}
  render "$input" --method reference -o "$TMP/${name}_reference.exr"
  variants=("chord 1")
  for r in $RADII; do variants+=("volume $r"); done
  for v in "${variants[@]}"; do
    set -- $v
    exr=$TMP/${name}_$1_$2.exr
    render "$input" --method raycast_pca --set raycast_pca.thick_weight="$1" --set raycast_pca.thick_radius="$2" -o "$exr"
    is_def=$(awk -v w="$1" -v r="$2" -v dw="$def_weight" -v dr="$def_radius" 'BEGIN { print (w == dw && r + 0 == dr + 0) ? 1 : 0 }')
    map=()
    if [ "$1" = chord ] && [ "$2" = 1 ]; then map=(--map "$TMP/${name}_map_old.png"); maps_old+=("$TMP/${name}_map_old.png"); fi
    if [ "$is_def" = 1 ]; then map=(--map "$TMP/${name}_map_default.png"); maps_new+=("$TMP/${name}_map_default.png"); fi
    "$TOOL" "${map[@]}" "$TMP/${name}_reference.exr" "$exr" | cut -d, -f2- |
      sed "s/^/$name,$1,$2,$is_def,/" >> "$TMP/thickness.csv"
  done
  echo "thickness: $name done"
done
[ ${#maps_new[@]} = 3 ] || { echo "thickness.sh: the default (radius $def_radius) is not among RADII ($RADII)" >&2; exit 2; }
mv "$TMP/thickness.csv" "$OUT/thickness.csv"
frames_mosaic "$OUT/thickness_heatmap.png" 3x2 "$(quick 256x256 64x64)" "${maps_old[@]}" "${maps_new[@]}"
echo "wrote $OUT/thickness.csv, $OUT/thickness_heatmap.png"
