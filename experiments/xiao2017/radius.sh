#!/usr/bin/env bash
# Sensitivity of issue 4's normal bars to the PCA / gradient radius R (4 r shipped):
# the jittered slab and box against `analytic` at 512^2, normals basic / blend
# (filter on), R = 3, 4, 5, 6 r; interior error and its split into faces >= 2r
# from an ideal edge and the 2r edge band (experiments/tools/edge_bands.c). It
# answers "is there an R at which blend beats basic at the edges?"; it does not
# change the default. Writes results/xiao2017/radius_sweep.csv.
# FS_QUICK=1 (experiments/lib.sh): 128^2, R = 3 and 4 r; into out/quick/results/xiao2017
# and out/quick/xiao2017/radius.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/edge_bands}
SIZE=$(quick 512 128)
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/radius
mkdir -p "$OUT" "$TMP"
for x in "$BIN" "$TOOL"; do [ -x "$x" ] || { echo "radius.sh: $x missing" >&2; exit 2; }; done
csv=$OUT/radius_sweep.csv
echo "scene,normals,pca_radius_r,interior_deg,face_deg,edge_band_deg" > "$csv.tmp"
for shape in slab box; do
  d=$TMP/$shape
  "$BIN" compare --force --no-cache "experiments/scenes/$shape.json" --methods raycast_pca --set raycast_pca.normals=basic,blend \
      --set raycast_pca.pca_radius=$(quick 3,4,5,6 3,4) --reference analytic -W $SIZE -H $SIZE --repeat 1 -q -o "$d" 2> "$TMP/$shape.log"
  "$TOOL" "experiments/scenes/$shape.json" "$d/analytic.exr" "$d"/raycast_pca_*.exr |
    awk -F, -v s="$shape" '!/^#/ && $1 != "file" {
        f = $1; sub(/.*raycast_pca_normals-/, "", f); sub(/\.exr$/, "", f);
        split(f, a, /_pca_radius-/); gsub(/p/, ".", a[2]); key = s "," a[1] "," a[2];
        v[key, $2] = $4; keys[key] = 1 }
      END { for (k in keys) printf "%s,%.2f,%.2f,%.2f\n", k, v[k, "interior"], v[k, "face"], v[k, "edge_band"] }' |
    sort >> "$csv.tmp"
done
publish "$csv"; stamp_csv "$csv"; column -t -s, "$csv"
