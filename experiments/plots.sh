#!/usr/bin/env bash
# The studies' trends as PNG plots (gnuplot, through experiments/tools/plot_csv.py),
# drawn from the CSVs under RESULTS (results/, or out/quick/results with FS_QUICK=1) and
# written beside them; the READMEs embed them. A CSV a study did not write is skipped
# with a note; a plot that fails stops the script. (bench/speed.sh draws its own
# time-and-memory plot, bench/speed.png; xiao2017/joint_sweep_plot.sh the joint sweep's.)
set -euo pipefail
cd "$(dirname "$0")/.."
source experiments/lib.sh # RESULTS, quick
P="python3 experiments/tools/plot_csv.py"
command -v gnuplot > /dev/null || { echo "plots.sh: gnuplot missing (scripts/setup.sh installs it)" >&2; exit 2; }
plot() { # CSV PNG ARGS...: CSV and PNG relative to RESULTS
  local csv=$RESULTS/$1 png=$RESULTS/$2
  shift 2
  if [ ! -f "$csv" ]; then echo "plots.sh: $csv not there: skipped"; return; fi
  $P "$csv" "$png" "$@"
}
LL=(--logx --logy)
plot xiao2017/table1.csv xiao2017/table1_growth.png --x particles --y ms_median --series size --where stage=frame "${LL[@]}" \
  --title "xiao2017 Table 1: raycast_pca frame time against particle count, per image size (llvmpipe)" --ylabel "frame (ms, median)"
plot xiao2017/fig10.csv xiao2017/fig10.png --x iso --y frame_ms --series scene --logy \
  --title "xiao2017 Fig. 10: raycast_pca frame time against the iso value (llvmpipe)" --ylabel "frame (ms, median)"
plot xiao2017/radius_sweep.csv xiao2017/radius_sweep.png --x pca_radius_r --y interior_deg --series scene,normals \
  --title "xiao2017: raycast_pca interior normal error against the PCA radius R" --xlabel "R (multiples of r)" --ylabel "interior normal error (deg)"
plot xu2022/fig9.csv xu2022/fig9.png --x particles --y frame_ms --series filter,anisotropy "${LL[@]}" \
  --title "xu2022 Fig. 9: aniso_ssf frame time against particle count, 1024^2 (llvmpipe)" --ylabel "frame (ms, median)"
plot xu2022/sigma_sweep.csv xu2022/sigma_sweep.png --x sigma_r --y interior_deg --series scene,filter,anisotropy \
  --title "xu2022: aniso_ssf interior normal error against the filter scale" --xlabel "sigma (multiples of r)" --ylabel "interior normal error (deg)"
plot inacio2010/tables.csv inacio2010/tables_total.png --x particles --y total_ms --series table,path "${LL[@]}" \
  --title "inacio2010 Tables I (ray casting) and II (spheres): frame time against particle count" --ylabel "frame (ms)"
plot inacio2010/tables.csv inacio2010/tables_simulation_pct.png --x particles --y simulation_pct --series table,path --logx \
  --title "inacio2010 Fig. 5: the simulation's share of the frame against particle count" --ylabel "simulation (% of the frame)"
plot bench/memory.csv bench/memory.png --x n --y peak_rss_kib_median --series method,input --where "state=after|current" "${LL[@]}" \
  --title "Peak memory against particle count (1024^2)" --xlabel particles --ylabel "peak RSS (KiB, median)"
echo "plots.sh: done"
