#!/usr/bin/env bash
# The READMEs' pivot tables, derived from the studies' long CSVs (experiments/tools/
# pivot_csv.py) under RESULTS (results/, or out/quick/results with FS_QUICK=1), so that
# no table in a README is typed by hand. Run after the studies (run_all.sh runs it last
# but one); a CSV a study did not write is skipped with a note.
set -euo pipefail
cd "$(dirname "$0")/.."
source experiments/lib.sh # RESULTS, quick
pivot() { # IN OUT ARGS...: relative to RESULTS
  local in=$RESULTS/$1 out=$RESULTS/$2
  shift 2
  if [ ! -f "$in" ]; then echo "readme_pivots.sh: $in not there: skipped"; return; fi
  python3 experiments/tools/pivot_csv.py "$in" "$out" "$@"
  echo "wrote $out"
}
bins=$(awk 'BEGIN { for (i = 0; i < 16; i++) printf "%sedge_dist_%.1f-%.1fr", i ? "," : "", i / 2, (i + 1) / 2 }')
pivot xiao2017/fig3_slab_bands.csv xiao2017/fig3_slab_table.csv --rows normals,filter --col region --val mean_deg \
  --cols interior,face,top,edge_band
pivot xiao2017/fig3_box_bands.csv xiao2017/fig3_box_table.csv --rows normals --col region --val mean_deg \
  --cols interior,face,top,edge_band,edge_band_interior --where filter=filter=on
pivot xiao2017/fig3_slab_bands.csv xiao2017/fig3_edge_profile.csv --rows normals --col region --val mean_deg \
  --cols "$bins" --where filter=filter=on --where "normals=basic|blend"
pivot xiao2017/table1.csv xiao2017/table1_frame.csv --rows label,particles --col size --val ms_median --where stage=frame --where method=raycast_pca
pivot xiao2017/table1.csv xiao2017/table1_stages_1024.csv --rows label,particles --col stage --val ms_median --where size="$(quick 1024 128)" --where method=raycast_pca
pivot xiao2017/table1_ratios.csv xiao2017/table1_growth.csv --rows series,particles --col size --val ratio_to_512
for scene in slab box; do
  pivot xu2022/fig6_${scene}_bands.csv xu2022/fig6_${scene}_table.csv --rows anisotropy,region --col filter --val mean_deg \
    --where "region=interior|face"
done
pivot inacio2010/sim_speed.csv inacio2010/sim_speed_table.csv --rows particles,boundary --col path --val ms_per_step
echo "readme_pivots.sh: done"
