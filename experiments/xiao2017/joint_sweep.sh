#!/usr/bin/env bash
# raycast_pca's normal error against R (pca_radius) and min_neighbors jointly, on the
# jittered slab and box (against `analytic`, split by experiments/tools/edge_bands into
# faces >= 2r from an ideal edge and the 2r edge band) and on the dam break (against
# `reference`). radius.sh varied R alone, so at R = 3r the default min_neighbors = 10
# switched PCA off and "blend equals basic" there was the fallback; here blend runs at
# every (R, min_neighbors) and basic (which has no min_neighbors) at every R.
#
#   joint_sweep.sh [--quick]     (--quick, the same as FS_QUICK=1 (experiments/lib.sh): 128^2,
#                                 R = 3 and 4 r, min_neighbors 4 and 10)
#
# Writes results/xiao2017/joint_sweep.csv and its plot joint_sweep.png (joint_sweep_plot.sh;
# quick: into out/quick/results/xiao2017/, work files in out/quick/xiao2017/joint/).
# It measures; it changes no default.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = --quick ]; then export FS_QUICK=1; fi
source experiments/lib.sh # RESULTS, quick, study_commit
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/edge_bands}
size=$(quick 512 128) radii=$(quick 3,4,5,6 3,4) mins=$(quick 4,7,10 4,10) OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/joint
for x in "$BIN" "$TOOL"; do [ -x "$x" ] || { echo "joint_sweep.sh: $x missing" >&2; exit 2; }; done
mkdir -p "$OUT" "$TMP"
csv=$OUT/joint_sweep.csv

# one compare per normals mode; variant files are raycast_pca_<P-V>_<P-V>.exr
sweep() { # scene reference normals sets... -> folder
  local scene=$1 ref=$2 normals=$3 d=$TMP/$1_$3_$size; shift 3
  "$BIN" compare --force --no-cache "experiments/scenes/$scene.json" --methods raycast_pca --set raycast_pca.normals=$normals \
      "$@" --reference "$ref" -W $size -H $size --repeat 1 -q -o "$d" 2> "$d.log" || { cat "$d.log" >&2; exit 1; }
  echo "$d"
}
# R and min_neighbors of a variant's file label ("...pca_radius-3_min_neighbors-4" or
# "...pca_radius-3p5": a '.' in a label is written 'p')
params_of() { echo "$1" | sed -n 's/.*pca_radius-\([0-9p]*\)\(_min_neighbors-\([0-9]*\)\)\{0,1\}.*/\1,\3/p' | tr p .; }

{
  for scene in slab box; do
    for normals in basic blend; do
      extra=(); [ $normals = blend ] && extra=(--set raycast_pca.min_neighbors=$mins)
      d=$(sweep $scene analytic $normals --set raycast_pca.pca_radius=$radii "${extra[@]}")
      for exr in "$d"/raycast_pca_*.exr; do
        p=$(params_of "$(basename "$exr" .exr)")
        "$TOOL" "experiments/scenes/$scene.json" "$d/analytic.exr" "$exr" |
          awk -F, -v s=$scene -v n=$normals -v p="$p" '!/^#/ && $1 != "file" { v[$2] = $4 }
            END { split(p, a, ","); printf "%s,%s,%s,%s,%.2f,%.2f,%.2f\n", s, n, a[1], (a[2] == "" ? "-" : a[2]),
                  v["interior"], v["face"], v["edge_band"] }'
      done
    done
  done
  for normals in basic blend; do
    extra=(); [ $normals = blend ] && extra=(--set raycast_pca.min_neighbors=$mins)
    d=$(sweep dam_break reference $normals --set raycast_pca.pca_radius=$radii "${extra[@]}")
    # metrics.csv's variant ("pca_radius=3;min_neighbors=4") and interior_normal_mean_deg, by name
    csv_awk -v n=$normals 'if (col("method") == "raycast_pca") { v = col("variant"); r = v; m = "-"
        sub(/.*pca_radius=/, "", r); sub(/[ _;].*/, "", r)
        if (v ~ /min_neighbors=/) { m = v; sub(/.*min_neighbors=/, "", m); sub(/[ _;].*/, "", m) }
        printf "dam_break,%s,%s,%s,%.2f,,\n", n, r, m, col("interior_normal_mean_deg") }' "$d/metrics.csv"
  done
} | sort -t, -k1,1 -k2,2 -k3,3n -k4,4n > "$csv.body"
renderer=$(sed -n '1s/.*gl_renderer=\([^;]*\);.*/\1/p' "$TMP/dam_break_blend_$size/metrics.csv")
{
  echo "# $STUDY_PROV; size=${size}x${size}; slab and box against analytic (edge_bands, band 2r), dam_break against reference; gl_renderer=$renderer"
  echo "scene,normals,pca_radius_r,min_neighbors,interior_deg,face_deg,edge_band_deg"
  cat "$csv.body"
} > "$csv.tmp"
rm "$csv.body"
publish "$csv"
column -t -s, "$csv"
bash experiments/xiao2017/joint_sweep_plot.sh "$csv"
