#!/usr/bin/env bash
# xu2022 Figs. 5 and 7 analogue (fluid-solid coupling): a dam break of 6000 particles
# (r = 0.02) runs into a static box and a ball (fig5_sim.json; the simulator makes them
# boundary particles). aniso_ssf renders frames 9 to 15 (t = 0.3 to 0.5 s, 30 fps) with
# isotropic and anisotropic sprites under every filter (none, gaussian, bilateral,
# curvature, narrow; shipped iterations), against both exact references (`reference`,
# the isotropic SPH iso-surface; `reference:field=anisotropic`, the surface the
# ellipsoids approximate). The shared shading draws the solids and the metrics leave out
# the pixels they hide. experiments/tools/solid_bands.c splits the normal error at the
# interface (reference surface within 3r of a solid) from the rest.
# Writes results/xu2022/fig5_metrics.csv (per frame), fig5_bands.csv (per frame),
# fig5_bands_summary.csv (pixel-weighted over the frames), fig5_interface.csv (per filter:
# in how many frames anisotropy lowers the interface error), fig5_row.png (reference,
# isotropic, anisotropic; narrow filter, t = 0.4 s) and fig7_grid.png (rows anisotropy
# off / on: the reference, then the five filters, cropped to the solids, t = 0.4 s).
# Work in out/xu2022/fig5/. FS_QUICK=1: r = 0.04 (750 particles), frames 11 to 12,
# 128^2, into out/quick/results.
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
FILTERS="none gaussian bilateral curvature narrow"
d=$TMP/compare
"$BIN" compare --force --no-cache "$TMP/scene.json" --methods aniso_ssf --set aniso_ssf.anisotropy=off,on \
    --set "aniso_ssf.filter=${FILTERS// /,}" --reference reference --reference reference:field=anisotropic \
    -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" -q 2> "$TMP/compare.log"
cp "$d/metrics.csv" "$OUT/fig5_metrics.csv"
{
  echo "# $(study_commit); simulate $SIM --radius $R, frames $FIRST..$LAST at 30 fps; solid_bands --band 3 at ${SIZE}x$SIZE"
  echo "frame,reference,anisotropy,filter,region,pixels,mean_deg,p95_deg,depth_mean_r"
  for f in $(seq "$FIRST" "$LAST"); do
    ff=$(printf _f%04d "$f") exrs=()
    for a in off on; do for x in $FILTERS; do exrs+=("$d/aniso_ssf_anisotropy-${a}_filter-$x$ff.exr"); done; done
    # each reference's file label, and its name in the CSVs (as before labels were file-safe)
    for pair in "reference reference" "reference_field-anisotropic reference_field=anisotropic"; do
      read -r ref name <<< "$pair"
      "$TOOL" --band 3 "$TMP/scene.json" "$d/$ref$ff.exr" "${exrs[@]}" | sed '/^#/d; /^file,/d' |
          sed "s|^$d/aniso_ssf_anisotropy-\([a-z]*\)_filter-\([a-z]*\)${ff}\.exr|$f,$name,\1,\2|"
    done
  done
} > "$TMP/fig5_bands.csv"
# Over the frames, pixel-weighted: one row per reference, filter and anisotropy.
awk -F, 'NR == 1 { print; next } NR == 2 { print "reference,filter,anisotropy,frames,visible_deg,interface_deg,away_deg,interface_px,away_px"; next }
  { k = $2 "," $4 "," $3; if (!(k in n)) order[++m] = k; if ($5 == "visible") n[k]++
    px[k, $5] += $6; deg[k, $5] += $6 * $7 }
  function mean(k, r) { return px[k, r] ? sprintf("%.4f", deg[k, r] / px[k, r]) : "nan" }
  END { for (i = 1; i <= m; i++) { k = order[i]
    printf "%s,%d,%s,%s,%s,%d,%d\n", k, n[k], mean(k, "visible"), mean(k, "interface"), mean(k, "away"), px[k, "interface"], px[k, "away"] } }' \
    "$TMP/fig5_bands.csv" > "$TMP/fig5_bands_summary.csv"
# Per filter: the frames in which anisotropy lowers the interface error, and the mean change.
awk -F, 'NR == 1 { print; next } NR == 2 { print "reference,filter,frames,frames_on_lower,mean_on_minus_off_deg"; next }
  $5 == "interface" { k = $2 "," $4; if (!(k in off)) order[++m] = k
    if ($3 == "off") { off[k] = $7 } else if ($7 != "nan" && off[k] != "nan") { n[k]++; low[k] += $7 < off[k]; dd[k] += $7 - off[k] } }
  END { for (i = 1; i <= m; i++) { k = order[i]; if (n[k]) printf "%s,%d,%d,%.4f\n", k, n[k], low[k], dd[k] / n[k]
                                                 else printf "%s,0,0,nan\n", k } }' \
    "$TMP/fig5_bands.csv" > "$TMP/fig5_interface.csv"
mv "$TMP"/fig5_bands.csv "$TMP"/fig5_bands_summary.csv "$TMP"/fig5_interface.csv "$OUT/"
stamp_csv "$OUT"/fig5_{metrics,bands,bands_summary,interface}.csv
show=$(printf _f%04d "$SHOW")
frames_mosaic "$OUT/fig5_row.png" 3x1 "$(quick 400x400 64x64)" "$d/reference$show.png" \
    "$d/aniso_ssf_anisotropy-off_filter-narrow$show.png" "$d/aniso_ssf_anisotropy-on_filter-narrow$show.png"
crop=$(quick 256x256+185+128 64x64+46+32) grid=()
for a in off on; do
  grid+=("$d/reference$show.png")
  for x in $FILTERS; do grid+=("$d/aniso_ssf_anisotropy-${a}_filter-$x$show.png"); done
done
frames_mosaic "$OUT/fig7_grid.png" 6x2 "$(quick 200x200 64x64)" --cut "$crop" "${grid[@]}"
echo "wrote $OUT/fig5_*.csv, $OUT/fig5_row.png, $OUT/fig7_grid.png"
