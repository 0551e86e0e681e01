#!/usr/bin/env bash
# Sensitivity of issue 5's bar (a) to the one filter scale every depth filter
# shares (`sigma`, 1.5 r shipped): the jittered slab and box against `analytic`
# at 512^2, filters gaussian and narrow, anisotropy off / on, sigma 0.5 / 1.0 /
# 1.5 r; interior error and its split into faces >= 2r from an ideal edge and the
# 2r edge band (experiments/tools/edge_bands.c). It answers "is there a sigma at
# which anisotropy helps the narrow-range filter on both scenes?"; it does not
# change the default. Writes results/xu2022/sigma_sweep.csv.
# FS_QUICK=1 (experiments/lib.sh): 128^2, sigma 0.5 and 1.5 r; into out/quick/results/xu2022
# and out/quick/xu2022/sigma.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/edge_bands}
SIZE=$(quick 512 128)
OUT=$RESULTS/xu2022
TMP=out/$(quick "" quick/)xu2022/sigma
mkdir -p "$OUT" "$TMP"
for x in "$BIN" "$TOOL"; do [ -x "$x" ] || { echo "sigma.sh: $x missing" >&2; exit 2; }; done
csv=$OUT/sigma_sweep.csv
echo "scene,filter,sigma_r,anisotropy,interior_deg,face_deg,edge_band_deg" > "$csv.tmp"
for shape in slab box; do
  d=$TMP/$shape
  "$BIN" compare --force --no-cache "experiments/scenes/$shape.json" --methods aniso_ssf --set aniso_ssf.filter=gaussian,narrow \
      --set aniso_ssf.sigma=$(quick 0.5,1.0,1.5 0.5,1.5) --set aniso_ssf.anisotropy=off,on --reference analytic \
      -W $SIZE -H $SIZE --repeat 1 -q -o "$d" 2> "$TMP/$shape.log"
  "$TOOL" "experiments/scenes/$shape.json" "$d/analytic.exr" "$d"/aniso_ssf_*.exr |
    awk -F, -v s="$shape" '!/^#/ && $1 != "file" {
        f = $1; sub(/.*aniso_ssf_filter-/, "", f); sub(/\.exr$/, "", f);
        split(f, a, /_sigma-|_anisotropy-/); gsub(/p/, ".", a[2]); key = s "," a[1] "," a[2] "," a[3];
        v[key, $2] = $4; keys[key] = 1 }
      END { for (k in keys) printf "%s,%.2f,%.2f,%.2f\n", k, v[k, "interior"], v[k, "face"], v[k, "edge_band"] }' |
    sort >> "$csv.tmp"
done
publish "$csv"; stamp_csv "$csv"; column -t -s, "$csv"
