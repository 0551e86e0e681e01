#!/usr/bin/env bash
# Derives everything else from speed.csv (experiments/bench/speed.sh calls it;
# it can be rerun on its own): speed_ratios.csv (the issue's targets as ratios
# measured in the one run), speed.png (log-log time and peak RSS against the
# particle count) and README-speed.md, all beside the CSV. No number in them is
# typed by hand.
#   experiments/bench/speed_report.sh [results/bench/speed.csv] ["SMALL MID LARGE" synthetic sets] [IMAGES]
# IMAGES: speed.sh's work folder with the set's images (default out/bench/speed; with
# FS_QUICK=1 the CSV defaults to out/quick/results/bench/speed.csv, the images to out/quick/bench/speed).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # quick, RESULTS
CSV=${1:-$RESULTS/bench/speed.csv}
GROWTH=${2:-$(quick "box_100k box_1m box_10m" "box_1k box_10k box_27k")}
DIR=$(dirname "$CSV")
RAT=$DIR/speed_ratios.csv PNG=$DIR/speed.png MD=$DIR/README-speed.md
[ -s "$CSV" ] || { echo "speed_report.sh: $CSV missing" >&2; exit 1; }
read -r G1 G2 G3 <<<"$GROWTH"
BASE=$(grep -m1 '^# baseline: ' "$CSV" | sed 's/^# baseline: reference@\([^ ]*\).*/\1/')
SIZE=$(awk -F, '!/^#/ && NR > 1 && $2 ~ /^[0-9]+$/ {if ($4 > m) m = $4} END {print m}' "$CSV")

# ---- ratios
awk -F, -v base="reference@$BASE" -v size="$SIZE" -v g1="$G1" -v g2="$G2" -v g3="$G3" '
  /^#/ || $1 == "set" { next }
  $15 == "ok" && $4 == size { t[$1, $3] = $8; m[$1, $3] = $11; s[$1, $3] = $13; n[$1] = $2; sets[$1] = 1; meth[$3] = 1; c[$1, $3] = $14 }
  $15 == "ok" && $4 == 8 && $3 == "reference" { fixed[$1] = $8 }
  $15 == "ok" && $4 == 8 && $3 == "reference to PNG" { fixedp[$1] = $8 }
  $15 == "ok" && $4 == 8 && $3 == base { fixedb[$1] = $8 }
  function row(q, set, method, v, target, ok) {
    printf "%s,%s,%s,%s,%s,%s\n", q, set, method, v == "" ? "" : sprintf("%.3g", v), target,
      v == "" ? "n/a" : (target == "" ? "" : (ok ? "yes" : "no"))
  }
  function ratio(a, b) { return (a != "" && b != "" && b > 0) ? a / b : "" }
  END {
    print "quantity,sets,method,value,target,met"
    v = ratio(t["splash", base], t["splash", "reference"]); row("speed-up vs " base " (whole process)", "splash", "reference", v, ">= 15", v >= 15)
    split("dualsphysics splash", vs, " ")
    for (i = 1; i <= 2; i++) if (t[vs[i], "reference"] != "") {
      v = ratio(t[vs[i], "vdb_tool"], t[vs[i], "reference"]); row("speed-up vs vdb_tool (whole process)", vs[i], "reference", v, ">= 1.5", v >= 1.5)
      v = ratio(t[vs[i], "vdb_tool"], t[vs[i], "reference thickness=off"]); row("speed-up vs vdb_tool (whole process)", vs[i], "reference thickness=off", v, "", 0)
    }
    for (k in sets) if (t[k, "levelset thickness=off"] != "") { v = ratio(t[k, "vdb_tool"], t[k, "levelset thickness=off"]); row("speed-up vs vdb_tool (whole process)", k, "levelset thickness=off", v, ">= 1", v >= 1) }
    row("fixed cost at 8x8 pixels (s)", "splash", "reference", fixed["splash"], "", 0)
    row("fixed cost at 8x8 pixels (s)", "splash", base, fixedb["splash"], "", 0)
    if (fixed["dam_break_7k"] != "") row("fixed cost at 8x8 pixels, EXR (s)", "dam_break_7k", "reference", fixed["dam_break_7k"], "<= 0.15", fixed["dam_break_7k"] <= 0.15)
    if (fixedp["dam_break_7k"] != "") row("fixed cost at 8x8 pixels, PNG (s)", "dam_break_7k", "reference", fixedp["dam_break_7k"], "<= 0.15", fixedp["dam_break_7k"] <= 0.15)
    for (k in sets) order[++ns] = k
    for (i = 1; i <= ns; i++) for (j = i + 1; j <= ns; j++) if (n[order[j]] + 0 < n[order[i]] + 0) { x = order[i]; order[i] = order[j]; order[j] = x }
    for (i = 1; i <= ns; i++) {
      k = order[i]
      if (c[k, "reference"] != "" && c[k, "reference"] + 0 == 0) continue # nothing covered: no ratio to speak of
      v = ratio(s[k, "reference"], s[k, "reference thickness=off"]); row("thickness cost on/off (march and bounds stages)", k, "reference", v, "", 0)
      v = ratio(t[k, "reference"], t[k, "reference thickness=off"]); row("thickness cost on/off (whole process)", k, "reference", v, "<= 1.5", v <= 1.5)
    }
    nm = split("reference|reference thickness=off|spheres|raycast_pca|vdb_tool", ms, "|")
    for (i = 1; i <= nm; i++) {
      q = ms[i]
      v = ratio(t[g3, q], t[g2, q]); row("time growth " g2 " -> " g3, g2 " -> " g3, q, v, q == "reference" ? "<= 4" : "", v <= 4)
    }
    for (i = 1; i <= nm; i++) {
      q = ms[i]; tg = (q == "vdb_tool" || q == "reference thickness=off") ? "" : "<= 96"
      v = (m[g1, q] != "" && m[g2, q] != "" && n[g2] > n[g1]) ? (m[g2, q] - m[g1, q]) * 1048576 / (n[g2] - n[g1]) : ""
      row("peak RSS bytes per particle " g1 " -> " g2, g1 " -> " g2, q, v, tg, v <= 96)
      v = (m[g2, q] != "" && m[g3, q] != "" && n[g3] > n[g2]) ? (m[g3, q] - m[g2, q]) * 1048576 / (n[g3] - n[g2]) : ""
      row("peak RSS bytes per particle " g2 " -> " g3, g2 " -> " g3, q, v, tg, v <= 96)
    }
  }' "$CSV" > "$RAT.body"
{ echo "# $(csv_commit "$CSV"); ratios of $(basename "$CSV") (experiments/bench/speed_report.sh)"; cat "$RAT.body"; } > "$RAT"
rm -f "$RAT.body"

# ---- plot: time and peak RSS against particles, log-log; lines join the synthetic boxes
tmpd=$(mktemp -d); trap 'rm -rf "$tmpd"' EXIT
methods=("reference" "reference thickness=off" "spheres" "raycast_pca" "levelset thickness=off" "vdb_tool" "reference@$BASE")
for i in "${!methods[@]}"; do
  awk -F, -v q="${methods[$i]}" -v size="$SIZE" '!/^#/ && $3 == q && $4 == size && $15 == "ok" {
      print $2, $8, $11, ($1 ~ /^box_/) ? 1 : 0, $1 }' "$CSV" | sort -g > "$tmpd/m$i.all"
  awk '$4 == 1' "$tmpd/m$i.all" > "$tmpd/m$i.box"; awk '$4 == 0' "$tmpd/m$i.all" > "$tmpd/m$i.real"
done
{
  echo "set terminal pngcairo size 1500,620 font 'DejaVu Sans,11'"
  echo "set output '$PNG'"
  echo "set multiplot layout 1,2 title \"fluidsurf speed benchmark, ${SIZE}x$SIZE, whole process, $(grep -m1 '^# fluidsurf' "$CSV" | sed 's/.*commit[ =]\([^;]*\);.*/commit \1/') (lines: synthetic boxes; open points: real frames)\""
  echo "set termoption noenhanced; set logscale xy; set grid; set key top left; set xlabel 'particles'; set offsets graph 0.04, graph 0.04, 0, 0"
  for panel in 2 3; do
    if [ $panel = 2 ]; then echo "set ylabel 'wall time (s)'"; else echo "set ylabel 'peak RSS (MiB)'"; fi
    printf 'plot '
    sep=""
    for i in "${!methods[@]}"; do
      [ -s "$tmpd/m$i.all" ] || continue
      [ -s "$tmpd/m$i.box" ] && { printf "%s'%s' using 1:%d with linespoints lc %d pt 7 title '%s'" "$sep" "$tmpd/m$i.box" $panel $((i + 1)) "${methods[$i]}"; sep=", "; }
      [ -s "$tmpd/m$i.real" ] && { printf "%s'%s' using 1:%d with points lc %d pt 6 ps 1.5 %s" "$sep" "$tmpd/m$i.real" $panel $((i + 1)) \
        "$([ -s "$tmpd/m$i.box" ] && echo notitle || echo "title '${methods[$i]}'")"; sep=", "; }
    done
    echo
  done
  echo "unset multiplot"
} > "$tmpd/plot.gp"
gnuplot "$tmpd/plot.gp"

# ---- the view check: fluidsurf's reference and vdb_tool's image of the splash frame, side by side
IMG=${3:-$(quick out/bench/speed out/quick/bench/speed)}
VIEW=$DIR/speed_view_splash.png
if [ -s "$IMG/splash.reference.exr" ] && [ -s "$IMG/splash.vdb_tool.png" ]; then
  oiiotool "$IMG/splash.reference.exr" --ch R,G,B --colorconvert linear sRGB --resize 400x400 -o "$tmpd/a.png" &&
    oiiotool "$IMG/splash.vdb_tool.png" --resize 400x400 -o "$tmpd/b.png" &&
    oiiotool "$tmpd/a.png" "$tmpd/b.png" --mosaic 2x1 -o "$VIEW" || rm -f "$VIEW"
fi

# ---- README
{
  echo "# Speed benchmark (issue 13, section 6)"
  echo
  echo "Generated by \`experiments/bench/speed_report.sh\` from \`$(basename "$CSV")\`; do not edit by hand."
  echo "Made by \`experiments/bench/speed.sh\` (full) or \`speed.sh --quick\` (smoke check: small sets, 128x128, 1 run, today's binary standing in for the baseline)."
  echo
  echo "## Provenance"
  echo
  grep '^#' "$CSV" | sed 's/^# /- /'
  echo
  echo "## The machine"
  echo
  echo "2 CPU cores (the load average in the provenance says how quiet they were), no GPU. The GL methods"
  echo "(\`spheres\`, \`raycast_pca\`) run on OSMesa's llvmpipe, i.e. on the same CPU cores as the C code,"
  echo "so nothing here says anything about GPU speed. \`reference\` and vdb_tool are CPU code."
  echo
  echo "## How it is measured"
  echo
  echo "- Each row is one method on one particle set: the whole process (start-up, loading, grids, the"
  echo "  method, shading, writing the image) timed by \`/usr/bin/time -f '%e %M'\`, the median of \`runs\`."
  echo "- Every fluidsurf binary (today's and \`reference@$BASE\`, the baseline commit built once into the"
  echo "  cache) gets a scene file that writes out the camera today's fluidsurf frames automatically for the set"
  echo "  (read back from its EXR provenance), so all see the same view. fluidsurf writes an EXR."
  echo "- \`vdb_tool\` (OpenVDB) runs \`-read SET.ply -points2ls voxel=r/2 radius=4 width=3 -render image=WxH"
  echo "  translate=(eye) target=(target) up=(up) aperture=36.4\` on the same points with that camera: \`radius\`"
  echo "  is in voxels, so the points become spheres of 4 x r/2 = 2r in world units; the aperture is the frame"
  echo "  width in mm at the default 50 mm focal length, 100 tan(fov/2) = 36.4 for fluidsurf's 40 degrees"
  echo "  (square images: horizontal = vertical field of view). Writing its PLY is not timed; reading it is."
  echo "- Sets: synthetic boxes (lattice 2r, jitter 0.1 r, seed 1, r = 0.025, generated in-process by"
  echo "  fluidsurf as part of its load), the bundled SPlisHSPlasH frames (\`experiments/data/splashsurf\`, read as bare"
  echo "  files: volume_scale 1, r = 0.025), the simulated splash frame (\`experiments/data/splash\`) and the third-party"
  echo "  DualSPHysics dam break just after impact (\`dualsphysics\`: \`../shared/data/dualsphysics/dambreak200k_t0.300.vtk\`,"
  echo "  z up, r = 0.00365 as its README gives; the camera looks through the full water depth)."
  echo "- \`levelset thickness=off\` is fluidsurf's OpenVDB level set method on the same view, first hits only as vdb_tool renders; \`reference to PNG\` writes a PNG instead of an EXR."
  echo
  echo "| column | meaning |"
  echo "|---|---|"
  echo "| set, particles | the particle set and its particle count |"
  echo "| method | fluidsurf method (\`reference\` has thickness on; \`reference thickness=off\` is \`--set reference.thickness=off\`), \`reference@$BASE\` (the baseline's reference, thickness on), or \`vdb_tool\` |"
  echo "| width, height | image size in pixels (rows at 8x8 measure the fixed cost: start-up, load, grid) |"
  echo "| runs, ok_runs | runs asked for, runs that succeeded (a failure stops the row; \`status\` failed, \`error\` its first line) |"
  echo "| wall_s_median, wall_s_min, wall_s_max | whole-process wall time over the runs, seconds |"
  echo "| peak_rss_mib_median, peak_rss_mib_max | whole-process peak resident memory, MiB (median and largest over the runs) |"
  echo "| stage_ms_median | fluidsurf's own \`--timings\` of the method's render stages (all but load, grid, upload, shade; the reference: bounds, interior and march), median, ms |"
  echo "| coverage | fraction of pixels covered: fluidsurf's coverage layer; vdb_tool's PNG: pixels that are not black (its background) |"
  echo
  echo "## Targets of the issue next to the measured ratios (\`speed_ratios.csv\`)"
  echo
  echo "| quantity | sets | method | measured | target | met |"
  echo "|---|---|---|---|---|---|"
  grep -v '^#' "$RAT" | tail -n +2 | awk -F, '{printf "| %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4 == "" ? "—" : $4, $5 == "" ? "—" : $5, $6}'
  echo
  echo "bytes per particle = (peak RSS of the larger set - peak RSS of the smaller) / (difference in particles)."
  echo "Thickness ratios are left out for a set where the reference covers no pixel."
  echo
  echo "Reading it: the machine is shared, and its load changes during a run by a factor of 2 or more, so a"
  echo "ratio of two rows measured minutes apart (the growth 1M -> 10M above all) carries that noise; the"
  echo "min - max columns and the load average in the header show how much. Judge the targets by a run on"
  echo "a quiet machine."
  echo
  echo "## All rows (\`speed.csv\`)"
  echo
  echo "| set | particles | method | size | wall s (median) | min - max | peak RSS MiB | stage ms | coverage | status |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  awk -F, '!/^#/ && $1 != "set" {printf "| %s | %s | %s | %sx%s | %s | %s - %s | %s | %s | %s | %s%s |\n", $1, $2, $3, $4, $5,
    $8 == "" ? "—" : $8, $9, $10, $11 == "" ? "—" : $11, $13 == "" ? "—" : $13, $14 == "" ? "—" : $14, $15,
    ($16 != "\"\"" ? " " $16 : "")}' "$CSV"
  echo
  echo "![time and peak RSS against particles]($(basename "$PNG"))"
  if [ -s "$VIEW" ]; then
    echo
    echo "The same view: the splash frame at $(awk -F, '!/^#/ && $1 == "splash" && $3 == "reference" && $4 > 8 {print $4 "x" $5; exit}' "$CSV"),"
    echo "fluidsurf's \`reference\` (shared shading; left) and \`vdb_tool\` (its diffuse shader; right), both scaled to 400x400;"
    echo "covered fractions $(awk -F, '!/^#/ && $1 == "splash" && $3 == "reference" && $4 > 8 {print $14; exit}' "$CSV") and"
    echo "$(awk -F, '!/^#/ && $1 == "splash" && $3 == "vdb_tool" {print $14; exit}' "$CSV") (vdb_tool's points become spheres of radius 2r; the reference's iso-surface lies about r out from the centres)."
    echo
    echo "![the splash frame: reference and vdb_tool, same camera]($(basename "$VIEW"))"
  fi
} > "$MD"
echo "speed_report.sh: wrote $RAT, $PNG, $MD" >&2
