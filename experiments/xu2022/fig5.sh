#!/usr/bin/env bash
# xu2022 Fig. 5 analogue (fluid-solid coupling): a dam break of 6000 particles (r = 0.02)
# runs into a static box and a ball (fig5_sim.json; the simulator makes them boundary
# particles), and aniso_ssf renders frames 9 to 15 (t = 0.3 to 0.5 s, 30 fps) with isotropic and with
# anisotropic sprites (narrow-range filter, the shipped default), against both exact
# references (`reference`, the isotropic SPH iso-surface; `reference:field=anisotropic`,
# the surface the ellipsoids approximate). The shared shading draws the solids; the
# metrics leave out the pixels they hide. experiments/tools/solid_bands.c splits the
# normal error at the interface (reference surface within 3r of a solid) from the rest.
# Writes results/xu2022/fig5_metrics.csv (per frame), fig5_bands.csv (per frame, both
# references), fig5_bands_summary.csv (pixel-weighted over the frames), fig5_interface.csv
# (the interface error per frame, off beside on) and fig5_row.png (reference, isotropic,
# anisotropic at t = 0.4 s). Work in out/xu2022/fig5/.
# FS_QUICK=1: r = 0.04 (750 particles), frames 11 to 12, 128^2, into out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, study_commit, simulated frames
BIN=${BIN:-./build/fluidsurf}
TOOL=${TOOL:-./build/experiments/solid_bands}
SIZE=${SIZE:-$(quick 512 128)}
R=${R:-$(quick 0.02 0.04)}
FIRST=${FIRST:-$(quick 9 11)} LAST=${LAST:-$(quick 15 12)} SHOW=${SHOW:-$(quick 12 12)} # frames, 30 per second
OUT=$RESULTS/xu2022
TMP=out/$(quick "" quick/)xu2022/fig5
SIM=experiments/xu2022/fig5_sim.json
mkdir -p "$OUT" "$TMP/frames"
for x in "$BIN" "$TOOL"; do
  [ -x "$x" ] || { echo "fig5.sh: $x missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
done
[ -f "$(printf "$TMP/frames/frame_%04d.bgeo" "$LAST")" ] ||
  "$BIN" simulate "$SIM" --radius "$R" --fps 30 --frames "$LAST" --cpu -q -o "$TMP/frames/frame_%04d.bgeo" \
      --stats "$TMP/frames/stats.csv"
# The render scene: the same solids (particles 0: the simulation ran at scale 1, so the
# scene's metres are the frame's), water over the checker, a view across the box.
python3 - "$SIM" "$TMP/scene.json" "$FIRST" "$LAST" "$R" "$SIZE" <<'PY'
import json, sys
sim, out, first, last, r, size = sys.argv[1:]
scene = {"particles": {"file": "frames/frame_%04d.bgeo", "first": int(first), "last": int(last)}, "radius": float(r), "up": "y", "material": "water", "background": "checker",
         "obstacles": json.load(open(sim))["obstacles"],
         "camera": {"eye": [1.75, 1.05, 2.15], "target": [0.85, 0.2, 0.4], "fov": 40, "width": int(size), "height": int(size)}}
json.dump(scene, open(out, "w"), indent=1)
PY
d=$TMP/compare
"$BIN" compare --no-cache "$TMP/scene.json" --methods aniso_ssf --set aniso_ssf.anisotropy=off,on \
    --reference reference --reference reference:field=anisotropic -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" -q \
    2> "$TMP/compare.log"
cp "$d/metrics.csv" "$OUT/fig5_metrics.csv"
{
  echo "# $(study_commit); simulate $SIM --radius $R, frames $FIRST..$LAST at 30 fps; solid_bands --band 3 at ${SIZE}x$SIZE"
  echo "frame,reference,anisotropy,region,pixels,mean_deg,p95_deg,depth_mean_r"
  for f in $(seq "$FIRST" "$LAST"); do
    for ref in reference reference_field=anisotropic; do
      ff=$(printf _f%04d "$f")
      "$TOOL" --band 3 "$TMP/scene.json" "$d/$ref$ff.exr" "$d/aniso_ssf_anisotropy=off$ff.exr" \
          "$d/aniso_ssf_anisotropy=on$ff.exr" | sed '/^#/d; /^file,/d' |
          sed "s|^$d/aniso_ssf_anisotropy=\([a-z]*\)${ff}\.exr|$f,$ref,\1|"
    done
  done
} > "$TMP/fig5_bands.csv"
# Over the frames: pixel-weighted means per reference, anisotropy and region.
awk -F, 'NR == 1 { print; next } NR == 2 { print "reference,anisotropy,region,frames,pixels,mean_deg,depth_mean_r"; next }
  { k = $2 "," $3 "," $4; if (!(k in n)) order[++m] = k; n[k]++; px[k] += $5; deg[k] += $5 * $6; dep[k] += $5 * $8 }
  END { for (i = 1; i <= m; i++) { k = order[i]; if (px[k]) printf "%s,%d,%d,%.4f,%.4f\n", k, n[k], px[k], deg[k] / px[k], dep[k] / px[k]
                                             else printf "%s,%d,0,nan,nan\n", k, n[k] } }' \
    "$TMP/fig5_bands.csv" > "$TMP/fig5_bands_summary.csv"
# The interface error per frame, off beside on.
awk -F, 'NR == 1 { print; next } NR == 2 { print "frame,reference,interface_pixels_off,off_deg,on_deg,on_minus_off_deg"; next }
  $4 == "interface" && $3 == "off" { off = $6; po = $5 }
  $4 == "interface" && $3 == "on" { printf "%s,%s,%s,%s,%s,%.4f\n", $1, $2, po, off, $6, $6 - off }' \
    "$TMP/fig5_bands.csv" > "$TMP/fig5_interface.csv"
mv "$TMP"/fig5_bands.csv "$TMP"/fig5_bands_summary.csv "$TMP"/fig5_interface.csv "$OUT/"
show=$(printf _f%04d "$SHOW")
frames_mosaic "$OUT/fig5_row.png" 3x1 "$(quick 400x400 64x64)" "$d/reference$show.png" \
    "$d/aniso_ssf_anisotropy=off$show.png" "$d/aniso_ssf_anisotropy=on$show.png"
echo "wrote $OUT/fig5_*.csv, $OUT/fig5_row.png"
