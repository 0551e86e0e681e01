#!/usr/bin/env bash
# xiao2017 Figs. 7 and 8 analogue, at a size this machine can simulate: a ball of water
# falls into a pool (fluidsurf's SPH `drop` scene, 30,000 particles at r = 0.025, CPU
# path), and raycast_pca renders the splash and the crown it throws up. The paper's Fig. 7
# is an 800k-particle splash under transparent shading (reflection and refraction), its
# Fig. 8 a 2M-particle crown under different materials.
#  - Fig. 7: three moments (impact, crown, collapse) under the scene's water material
#    (Fresnel reflection, refraction through the thickness, absorption), compared
#    against the exact `reference` (same shading).
#  - Fig. 8: the crown rendered by raycast_pca under three materials: clear
#    water, a dark-tinted liquid (stronger absorption, IOR 1.45), and opaque.
# Writes results/xiao2017/fig7.csv (per moment: metrics against the reference),
# fig7_raycast_pca.png, fig7_reference.png (the three moments) and fig8_materials.png.
# Work in out/xiao2017/fig7/. FS_QUICK=1: 3,000 particles, 128^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, study_commit, auto_camera, simulated_frames, frame_scene, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
N=${N:-$(quick 30000 3000)}
# at 60 fps. The tank scales with the count (cbrt), so the fall takes sqrt of that longer:
# impact, crown, collapse at t = 0.47, 0.65, 0.92 s (30,000) or 0.32, 0.43, 0.62 s (3,000).
FRAMES=${FRAMES:-$(quick "28 39 55" "19 26 37")}
CROWN=${CROWN:-$(quick 39 26)}
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/fig7
mkdir -p "$OUT" "$TMP/sim"
[ -x "$BIN" ] || { echo "fig7.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
last=$(tr ' ' '\n' <<< "$FRAMES" | sort -n | tail -1)
pat=$TMP/sim/frame_%04d.bgeo
simulated_frames "$BIN" drop "$N" "$last" "$pat"
frame_scene "$pat" "$CROWN" "$SIZE" > "$TMP/frame_crown.json"
auto_camera "$BIN" "$TMP/frame_crown.json" "$TMP"
{
  printf '# %s; particles=%s; sequence=simulate drop at 60 fps; raycast_pca against reference, water shading, %sx%s\n' \
    "$(study_commit)" "$N" "$SIZE" "$SIZE"
  echo "frame,t_s,mask_iou,depth_p95_r,normal_mean_deg,interior_normal_mean_deg,psnr_db,ssim,frame_ms"
} > "$TMP/fig7.csv"
for f in $FRAMES; do
  frame_scene "$pat" "$f" "$SIZE" "$P_CAMERA" > "$TMP/frame_$f.json"
  d=$TMP/frame_$f
  "$BIN" compare --force --no-cache "$TMP/frame_$f.json" --methods raycast_pca --reference reference \
      --repeat "$(quick 3 1)" -o "$d" -q 2> "$d.log"
  awk -F, -v f="$f" '$1 == "raycast_pca" { printf "%s,%.3f,%s,%s,%s,%s,%s,%s,%s\n", f, f / 60, $5, $8, $9, $11, $12, $13, $14 }' \
      "$d/metrics.csv" >> "$TMP/fig7.csv"
  echo "fig7: frame $f done"
done
mv "$TMP/fig7.csv" "$OUT/fig7.csv"
for m in raycast_pca reference; do
  frames_mosaic "$OUT/fig7_$m.png" 3x1 "$(quick 400x400 64x64)" $(for f in $FRAMES; do echo "$TMP/frame_$f/$m.png"; done)
done
# Fig. 8: the crown frame under three materials (the render is deterministic: one surface)
python3 - "$TMP/frame_$CROWN.json" "$TMP" <<'PY'
import json, sys
scene, out = json.load(open(sys.argv[1])), sys.argv[2]
materials = {"water": "water",
             "tinted": {"type": "water", "color": [0.75, 0.55, 0.35], "ior": 1.45, "absorption": [6.0, 9.0, 14.0]},
             "opaque": {"type": "opaque", "color": [0.55, 0.75, 0.95]}}
for name, m in materials.items():
    scene["material"] = m
    json.dump(scene, open("%s/material_%s.json" % (out, name), "w"))
PY
imgs=()
for m in water tinted opaque; do
  "$BIN" render "$TMP/material_$m.json" --method raycast_pca -q -o "$TMP/material_$m.png"
  imgs+=("$TMP/material_$m.png")
done
frames_mosaic "$OUT/fig8_materials.png" 3x1 "$(quick 400x400 64x64)" "${imgs[@]}"
echo "wrote $OUT/fig7.csv, $OUT/fig7_raycast_pca.png, $OUT/fig7_reference.png, $OUT/fig8_materials.png"
