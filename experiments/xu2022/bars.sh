#!/usr/bin/env bash
# Issue 5's bars for aniso_ssf (shipped defaults: anisotropy on, filter narrow,
# 2 iterations / curvature flow 80; default jitter 0.1 r), read from the outputs of
# fig6.sh (metrics CSVs, and the slab EXRs in out/xu2022/fig6/slab for the
# curvature-flow coverage check with `fluidsurf diff`) and fig9.sh (timings.csv).
# Writes results/xu2022/bars.csv: bar,measured,threshold,verdict,note.
# FS_QUICK=1 (experiments/lib.sh): reads and writes out/quick/results/xu2022 and reads
# out/quick/xu2022/fig6/slab (the quick runs of fig6.sh and fig9.sh: 128^2, the speed rows
# on the dam break and box_8k).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
BIN=${BIN:-./build/fluidsurf}
R=$RESULTS/xu2022
S=out/$(quick "" quick/)xu2022/fig6/slab
SIZE=$(quick 512 128) SPEED=$(quick 1024 128) BOX=$(quick box_1m box_8k) # fig6.sh's size, fig9.sh's
for f in $R/fig6_slab_metrics.csv $R/fig6_box_metrics.csv $R/timings.csv \
         "$S/aniso_ssf_anisotropy-on_filter-curvature.exr" "$S/aniso_ssf_anisotropy-on_filter-none.exr"; do
  [ -f "$f" ] || { echo "bars.sh: $f missing: run fig6.sh and fig9.sh first" >&2; exit 2; }
done
# metric FILE VARIANT COLUMN: a column of metrics.csv for one variant (by name: lib.sh)
metric() { csv_awk -v v="$2" 'if (col("variant") == v) print col("'"$3"'")' "$1"; }
# diffval A B KEY: one metric of `fluidsurf diff A B` (B the reference)
diffval() { "$BIN" diff "$1" "$2" | awk -v k="$3" '$1 == k {print $2}'; }
# stage LABEL ANISO FILTER STAGE: median ms from timings.csv
stage() { awk -F, -v l="$1" -v a="$2" -v f="$3" -v s="$4" '$1 == l && $3 == a && $4 == f && $5 == s {print $6}' $R/timings.csv; }
verdict() { awk "BEGIN {print ($1) ? \"pass\" : \"FAIL\"}"; }
renderer=$(awk -F, '!/^#/ && NR > 4 {print $8; exit}' $R/timings.csv | tr -d '"' | tr ',' ';')
csv=$R/bars.csv
{
  echo "# $(csv_commit $R/fig6_slab_metrics.csv $R/fig6_box_metrics.csv $R/timings.csv); issue 5 bars, aniso_ssf shipped defaults; from fig6_*_metrics.csv, $S/*.exr, timings.csv ($renderer)"
  echo "bar,measured,threshold,verdict,note"
  # (a) anisotropic vs isotropic sprites, both with the narrow-range filter
  for s in slab box; do
    on=$(metric $R/fig6_${s}_metrics.csv "anisotropy=on;filter=narrow" interior_normal_mean_deg)
    off=$(metric $R/fig6_${s}_metrics.csv "anisotropy=off;filter=narrow" interior_normal_mean_deg)
    echo "a_${s}_interior_aniso_narrow_deg,$on,< isotropic+narrow $off,$(verdict "$on < $off"),against analytic; ${SIZE}^2; interior = >= 3 px from silhouettes"
  done
  # (b) curvature flow (80 iterations) vs no filter on the slab
  for a in on off; do
    cf=$(metric $R/fig6_slab_metrics.csv "anisotropy=$a;filter=curvature" interior_normal_mean_deg)
    nf=$(metric $R/fig6_slab_metrics.csv "anisotropy=$a;filter=none" interior_normal_mean_deg)
    iou=$(diffval "$S/aniso_ssf_anisotropy-${a}_filter-curvature.exr" "$S/aniso_ssf_anisotropy-${a}_filter-none.exr" mask_iou)
    tag=""; [ "$a" = on ] || tag=" (not the shipped default: anisotropy off)"
    echo "b_slab_curvature_aniso_${a}_interior_deg,$cf,< no filter $nf,$(verdict "$cf < $nf"),80 iterations; dt = z/(2 f_px)$tag"
    echo "b_slab_curvature_aniso_${a}_coverage_iou,$iou,>= 0.98,$(verdict "$iou >= 0.98"),fluidsurf diff curvature.exr none.exr$tag"
  done
  # (c) speed at 1024^2, default filter (narrow), anisotropy on vs off
  for l in dam_break_24k $BOX; do
    on=$(stage $l on narrow frame); off=$(stage $l off narrow frame)
    split=""
    for st in anisotropy splat filter normals thickness readback; do split="$split $st=$(stage $l on narrow $st)"; done
    ratio=$(awk -v a="$on" -v b="$off" 'BEGIN {printf "%.2f", a / b}')
    echo "c_speed_${l}_${SPEED}_ms,$on,report,measured,$renderer; narrow filter; stages ms:$split; anisotropy off: $off ms; on/off = ${ratio}x"
  done
} > "$csv.tmp"
publish "$csv"
column -t -s, "$csv"
