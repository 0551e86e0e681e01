#!/usr/bin/env bash
# xu2022 Fig. 4 analogue: two water blocks colliding, isotropic against anisotropic sprites.
# The bundled double dam break frame (fig6.sh) is a film one particle thick on the floor; this
# study simulates its own: `fluidsurf simulate double_dam_break` (fluidsurf's SPH, CPU,
# deterministic) with N particles (default 16,000, r 0.025), frames 0..LAST (default 45) at
# 60 fps, and measures every frame (experiments/tools/sph_frames.py).
# Frame rule: the first frame whose collision sheet (the highest particle within 0.1 m of the
# tank's middle) stands as high as the columns stood at rest (frame 0's 99.9th-percentile
# height): the blocks have met and thrown up a thick, fast sheet. The contact frame (the first
# where a particle of one block is within 2 r of one of the other) is reported beside it.
# On the chosen frame: fig6.sh's grid (aniso_ssf, anisotropy off / on x filter none /
# gaussian / bilateral / curvature / narrow) at SIZE^2 (default 512) against `reference` and
# `reference:field=anisotropic`, under one camera looking at the tank's middle (scaled with
# the tank); the images cropped to the tank.
# Writes results/xu2022/fig4_collision_{frames.csv,metrics.csv,grid.png,pair.png,panel.png}:
# frames.csv the per-frame measures and the chosen frames; pair.png the reference and
# anisotropy off / on with the shipped filter (narrow-range), the paper's Fig. 4 (a) / (b).
# Work in out/xu2022/fig4_collision/. FS_QUICK=1: 4,000 particles, 40 frames, 128^2.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, stamp_csv, frame_scene, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
N=${N:-$(quick 16000 4000)}
LAST=${LAST:-$(quick 45 40)}
OUT=$RESULTS/xu2022
TMP=out/$(quick "" quick/)xu2022/fig4_collision
mkdir -p "$OUT" "$TMP/sim"
[ -x "$BIN" ] || { echo "fig4_collision.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
pat=$TMP/sim/frame_%04d.ply
rm -f "$TMP"/sim/frame_*.ply
nice -n 19 "$BIN" simulate double_dam_break --cpu --particles "$N" --frames "$LAST" -o "$pat" \
    --stats "$TMP/sim/stats.csv" -q
r=$("$BIN" info "$(printf "$pat" 0)" | awk '/^radius r:/ {print $3}')
files=()
for ((f = 0; f <= LAST; f++)); do files+=("$(printf "$pat" "$f")"); done
python3 experiments/tools/sph_frames.py "$r" "${files[@]}" |
    awk -F, 'NR == 1 {print "frame," $0; next} {print NR - 2 "," $0}' | sed 's|,[^,]*/frame_[0-9]*\.ply,|,|; 1s/,file,/,/' \
    > "$TMP/frames.csv"
# the rule, on the measures
read -r contact chosen h0 < <(awk -F, -v r="$r" 'NR == 1 {for (i = 1; i <= NF; i++) C[$i] = i; next}
    $C["frame"] == 0 { h0 = $C["y_p999"] }
    contact == "" && $C["min_dist"] != "" && $C["min_dist"] <= 2 * r { contact = $C["frame"] }
    contact != "" && chosen == "" && $C["mid_top"] >= h0 { chosen = $C["frame"] }
    END { print (contact == "" ? "none" : contact), (chosen == "" ? "none" : chosen), h0 }' "$TMP/frames.csv")
if [ "$chosen" = none ]; then
  echo "fig4_collision.sh: no frame up to $LAST has a collision sheet as high as the columns (${h0} m): raise LAST" >&2
  exit 1
fi
{
  echo "# $STUDY_PROV; simulate double_dam_break --cpu --particles $N --frames $LAST at 60 fps; r $r;" \
       "rule: chosen = first frame after contact with mid_top >= frame 0's y_p999 ($h0 m);" \
       "contact = first frame with min_dist <= 2 r; contact=$contact; chosen=$chosen"
  awk -F, -v c="$contact" -v s="$chosen" 'NR == 1 {print $0 ",t_s,pick"; next}
      {p = ($1 == s) ? "chosen" : ($1 == c) ? "contact" : ""; printf "%s,%.4f,%s\n", $0, $1 / 60, p}' "$TMP/frames.csv"
} > "$OUT/fig4_collision_frames.csv"
echo "fig4_collision: contact at frame $contact, chosen frame $chosen"

# one camera on the tank's middle, scaled with the tank (frame 0's bounds)
read -r x0 y0 z0 x1 y1 z1 < <("$BIN" info "$(printf "$pat" 0)" | awk '/^bbox min:/ {a = $3 " " $4 " " $5} /^bbox max:/ {print a, $3, $4, $5}')
CAM=$(awk -v x0="$x0" -v y0="$y0" -v z0="$z0" -v x1="$x1" -v y1="$y1" -v z1="$z1" 'BEGIN {
    k = (y1 - y0) / 1.2; tx = (x0 + x1) / 2; ty = y0 + 0.45 * (y1 - y0); tz = (z0 + z1) / 2
    printf "\"eye\": [%.3f, %.3f, %.3f], \"target\": [%.3f, %.3f, %.3f], \"up\": [0, 1, 0], \"fov\": 40",
        tx + 1.6 * k, ty + 1.5 * k, tz + 4.1 * k, tx, ty, tz }')
frame_scene "$pat" "$chosen" "$SIZE" "$CAM" > "$TMP/frame_$chosen.json"
FILTERS="none gaussian bilateral curvature narrow"
d=$TMP/frame_$chosen
nice -n 19 "$BIN" compare --force --no-cache "$TMP/frame_$chosen.json" --methods aniso_ssf \
    --set aniso_ssf.anisotropy=off,on --set "aniso_ssf.filter=${FILTERS// /,}" \
    --reference reference --reference reference:field=anisotropic -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" -q 2> "$d.log"
cp "$d/metrics.csv" "$OUT/fig4_collision_metrics.csv"
stamp_csv "$OUT/fig4_collision_metrics.csv" "$OUT/fig4_collision_frames.csv"
oiiotool "$d/panel.png" --resize "$(quick 640x0 320x0)" --ch R,G,B -o "$OUT/fig4_collision_panel.png"
# the tank's part of the image (CROP in pixels at 512^2, scaled to SIZE), 8:5 tiles
crop=$(echo 480x300+16+130 | awk -F'[x+]' -v s="$SIZE" '{f = s / 512; printf "%dx%d+%d+%d", $1 * f, $2 * f, $3 * f, $4 * f}')
tile=$(quick 240x150 96x60)
args=()
for a in off on; do
  args+=("$d/reference.png" --cut "$crop" --resize "$tile")
  for f in $FILTERS; do args+=("$d/aniso_ssf_anisotropy-${a}_filter-$f.png" --cut "$crop" --resize "$tile"); done
done
oiiotool "${args[@]}" --mosaic 6x2 --ch R,G,B -o "$OUT/fig4_collision_grid.png"
frames_mosaic "$OUT/fig4_collision_pair.png" 3x1 "$(quick 480x300 96x60)" --cut "$crop" "$d/reference.png" \
    "$d/aniso_ssf_anisotropy-off_filter-narrow.png" "$d/aniso_ssf_anisotropy-on_filter-narrow.png"
echo "wrote $OUT/fig4_collision_*"
