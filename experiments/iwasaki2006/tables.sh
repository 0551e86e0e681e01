#!/usr/bin/env bash
# The README's wide tables of iwasaki2006, derived from the studies' long CSVs (one row
# per method or stage) so that no number in the README is typed by hand:
#   density_grid_table.csv  per set and grid: exact CPU and slice-splat ms, their ratio,
#                           the relative L2 difference and the disks drawn (density_grid.csv)
#   surfels_table.csv       per scene and caustics on/off: surfels and every stage's ms (surfels.csv)
# Each keeps its source's first provenance line. Run after density_grid.sh and surfels.sh.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS
D=$RESULTS/iwasaki2006
for f in density_grid surfels; do
  [ -f "$D/$f.csv" ] || { echo "tables.sh: $D/$f.csv missing: run experiments/iwasaki2006/$f.sh first" >&2; exit 2; }
done
{
  echo "# from density_grid.csv: $(sed -n '1s/^# *//p' "$D/density_grid.csv")"
  echo "set,particles,res,exact_cpu_ms,slice_splat_ms,exact_over_splat,rel_l2_vs_exact,disks"
  awk -F, '!/^#/ && $1 != "set" { k = $1 "," $2 "," $3; if (!(k in seen)) { seen[k] = 1; order[++n] = k }
      if ($4 == "exact_cpu") ex[k] = $5; else { sp[k] = $5; l2[k] = $6; dk[k] = $7 } }
    END { for (i = 1; i <= n; i++) { k = order[i]
      printf "%s,%s,%s,%.2f,%s,%s\n", k, ex[k], sp[k], ex[k] / sp[k], l2[k], dk[k] } }' "$D/density_grid.csv"
} > "$D/density_grid_table.csv"
{
  echo "# from surfels.csv: $(sed -n '1s/^# *//p' "$D/surfels.csv")"
  stages=$(awk -F, '!/^#/ && $1 != "scene" && !seen[$5]++ { printf "%s%s", sep, $5; sep = "," }' "$D/surfels.csv")
  echo "scene,particles,surfels,caustics,${stages//,/_ms,}_ms"
  awk -F, -v stages="$stages" 'BEGIN { ns = split(stages, st, ",") }
    !/^#/ && $1 != "scene" { k = $1 "," $2 "," $3 "," $4; if (!(k in seen)) { seen[k] = 1; order[++n] = k }; ms[k, $5] = $6 }
    END { for (i = 1; i <= n; i++) { k = order[i]; line = k
      for (j = 1; j <= ns; j++) line = line "," ((k, st[j]) in ms ? ms[k, st[j]] : "")
      print line } }' "$D/surfels.csv"
} > "$D/surfels_table.csv"
echo "wrote $D/density_grid_table.csv, $D/surfels_table.csv"
