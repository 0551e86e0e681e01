#!/usr/bin/env bash
# The joint sweep as a plot (gnuplot): interior normal error against R for basic and
# for blend at each min_neighbors, one panel per scene.
#   joint_sweep_plot.sh [CSV [PNG]]   (default results/xiao2017/joint_sweep.{csv,png})
set -euo pipefail
cd "$(dirname "$0")/../.."
csv=${1:-results/xiao2017/joint_sweep.csv} png=${2:-${csv%.csv}.png}
command -v gnuplot > /dev/null || { echo "joint_sweep_plot.sh: gnuplot missing (scripts/setup.sh installs it)" >&2; exit 2; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# one data file per scene and curve: R, interior_deg
awk -F, -v d="$tmp" '!/^#/ && $1 != "scene" { c = ($2 == "basic") ? "basic" : "blend_" $4; print $3, $5 > (d "/" $1 "_" c ".dat") }' "$csv"
mins=$(awk -F, '!/^#/ && $2 == "blend" { print $4 }' "$csv" | sort -un | tr '\n' ' ')
prov=$(head -1 "$csv" | sed 's/^# //; s/;.*//')
{
  echo "set terminal pngcairo size 1200,380 font ',10' noenhanced"
  echo "set output '$png'"
  echo "set multiplot layout 1,3 title 'raycast_pca interior normal error against R ($prov)'"
  for scene in slab box dam_break; do
    ref=analytic; [ $scene = dam_break ] && ref=reference
    echo "set title '$scene (against $ref)'; set xlabel 'R (multiples of r)'; set ylabel 'interior normal error (deg)'; set key top right; set grid"
    line="plot '$tmp/${scene}_basic.dat' using 1:2 with linespoints lw 2 title 'basic'"
    for m in $mins; do line="$line, '$tmp/${scene}_blend_$m.dat' using 1:2 with linespoints title 'blend, min_neighbors $m'"; done
    echo "$line"
  done
  echo "unset multiplot"
} > "$tmp/plot.gp"
gnuplot "$tmp/plot.gp"
echo "wrote $png"
