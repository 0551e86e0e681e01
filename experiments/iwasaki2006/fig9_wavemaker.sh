#!/usr/bin/env bash
# iwasaki2006 Fig. 9 analogue: waves made by a moving wall, rendered with surfels.
# The paper's Fig. 9 is an MPS simulation of making waves ("complex shape of water
# surfaces"). Here fluidsurf's SPH (`simulate`, CPU, deterministic) shakes a tank
# (experiments/iwasaki2006/wavemaker_tank.json: 1.0 x 1.0 x 0.45 m, water 0.3 m deep,
# r 0.015) along x with `--shake A --shake-period T` (defaults 0.15 m, 1.3 s: the tank's first
# sloshing mode), so its end walls push the water as wave makers; frames 0..LAST (default 78)
# at 30 fps, each measured by experiments/tools/sph_frames.py.
# Frame rule: the frame of highest run-up (the largest 99.9th-percentile height of the
# water; the first such frame), and the three frames a quarter, a half and three quarters of
# a period before it (the wave that builds it). Each of the four against `reference` with
# surfels.sh's variants (surfels, caustics on / off) at SIZE^2 (default 512), one fixed
# camera that keeps the moving tank and the run-up in view.
# Writes results/iwasaki2006/fig9_wavemaker_{frames.csv,metrics.csv,own.png,shared.png,
# reference.png,panel.png}: own / shared / reference are the four frames in time order
# (surfels' own appearance with caustics; surfels in the shared shading; the exact
# iso-surface); panel.png is compare's panel of the run-up frame.
# Work in out/iwasaki2006/fig9_wavemaker/. FS_QUICK=1: r 0.03 (about 1,500 particles),
# 40 frames, 128^2.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick, stamp_csv, frame_scene, frames_mosaic
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
RADIUS=${RADIUS:-$(quick 0.015 0.03)}
LAST=${LAST:-$(quick 78 40)}
FPS=30 SHAKE=${SHAKE:-0.15} PERIOD=${PERIOD:-1.3}
OUT=$RESULTS/iwasaki2006
TMP=out/$(quick "" quick/)iwasaki2006/fig9_wavemaker
mkdir -p "$OUT" "$TMP/sim"
[ -x "$BIN" ] || { echo "fig9_wavemaker.sh: $BIN missing: cmake -S . -B build && cmake --build build" >&2; exit 2; }
pat=$TMP/sim/frame_%04d.ply
rm -f "$TMP"/sim/frame_*.ply
nice -n 19 "$BIN" simulate experiments/iwasaki2006/wavemaker_tank.json --cpu --radius "$RADIUS" --shake "$SHAKE" \
    --shake-period "$PERIOD" --fps "$FPS" --frames "$LAST" -o "$pat" --stats "$TMP/sim/stats.csv" -q
files=()
for ((f = 0; f <= LAST; f++)); do files+=("$(printf "$pat" "$f")"); done
python3 experiments/tools/sph_frames.py "$RADIUS" "${files[@]}" |
    awk -F, 'NR == 1 {print "frame," $0; next} {print NR - 2 "," $0}' | sed 's|,[^,]*/frame_[0-9]*\.ply,|,|; 1s/,file,/,/' \
    > "$TMP/frames.csv"
q=$(awk -v p="$PERIOD" -v f="$FPS" 'BEGIN {printf "%d", p * f / 4 + 0.5}') # a quarter period in frames
top=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) C[$i] = i; next}
    $C["y_p999"] > best {best = $C["y_p999"]; f = $C["frame"]} END {print f}' "$TMP/frames.csv")
if [ "$top" -lt $((3 * q)) ]; then
  echo "fig9_wavemaker.sh: the highest run-up is at frame $top, before three quarters of a period ($((3 * q)) frames)" >&2
  exit 1
fi
FRAMES="$((top - 3 * q)) $((top - 2 * q)) $((top - q)) $top"
n=$(awk -F, 'NR == 2 {print $2}' "$TMP/frames.csv")
{
  echo "# $STUDY_PROV; simulate experiments/iwasaki2006/wavemaker_tank.json --cpu --radius $RADIUS --shake $SHAKE" \
       "--shake-period $PERIOD --fps $FPS --frames $LAST; $n particles; rule: run-up = the frame of largest y_p999;" \
       "sequence = run-up - 3, 2, 1 quarter periods ($q frames); frames=${FRAMES// /,}"
  awk -F, -v fr=" $FRAMES " -v top="$top" 'NR == 1 {print $0 ",t_s,pick"; next}
      {p = ($1 == top) ? "run-up" : index(fr, " " $1 " ") ? "sequence" : ""; printf "%s,%.4f,%s\n", $0, $1 / 30, p}' \
      "$TMP/frames.csv"
} > "$OUT/fig9_wavemaker_frames.csv"
echo "fig9_wavemaker: run-up at frame $top; frames $FRAMES"

# one camera on the tank (its file's coordinates), high and far enough for the run-up
P_CAMERA='"eye": [1.75, 1.4, 2.7], "target": [0.5, 0.45, 0.225], "up": [0, 1, 0], "fov": 40'
metrics=$TMP/metrics.csv
rm -f "$metrics"
for f in $FRAMES; do
  frame_scene "$pat" "$f" "$SIZE" "$P_CAMERA" > "$TMP/frame_$f.json"
  d=$TMP/frame_$f
  nice -n 19 "$BIN" compare --force --no-cache "$TMP/frame_$f.json" --methods surfels --set surfels.caustics=on,off \
      -W "$SIZE" -H "$SIZE" --repeat 1 -o "$d" -q 2> "$d.log"
  [ -f "$metrics" ] || sed -n '1,2p' "$d/metrics.csv" > "$metrics"
  awk -F, -v OFS=, -v f="$f" 'NR == 2 {for (i = 1; i <= NF; i++) C[$i] = i} NR > 2 {$C["frame"] = f; print}' \
      "$d/metrics.csv" >> "$metrics"
  echo "fig9_wavemaker: frame $f done"
done
cp "$metrics" "$OUT/fig9_wavemaker_metrics.csv"
stamp_csv "$OUT/fig9_wavemaker_metrics.csv" "$OUT/fig9_wavemaker_frames.csv"
tile=$(quick 320x320 96x96)
for spec in own:surfels_caustics-on_own shared:surfels_caustics-on reference:reference; do
  frames_mosaic "$OUT/fig9_wavemaker_${spec%%:*}.png" 4x1 "$tile" $(for f in $FRAMES; do echo "$TMP/frame_$f/${spec#*:}.png"; done)
done
oiiotool "$TMP/frame_$top/panel.png" --resize "$(quick 640x0 320x0)" --ch R,G,B -o "$OUT/fig9_wavemaker_panel.png"
echo "wrote $OUT/fig9_wavemaker_*"
