#!/usr/bin/env bash
# Issue 4's bars for raycast_pca, read from the CSVs that fig3.sh and table1.sh
# wrote (shipped defaults = normals=blend, normal_filter=on; default jitter).
# Writes results/xiao2017/bars.csv: bar,measured,threshold,verdict,note.
# FS_QUICK=1 (experiments/lib.sh): reads and writes out/quick/results/xiao2017 (the quick
# runs of fig3.sh and table1.sh: 128^2, the speed rows at 128^2 on the dam break and box_8k).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, quick
R=$RESULTS/xiao2017
SPEED=$(quick 1024 128) BOX=$(quick box_1m box_8k) # table1.sh's speed cells
for f in fig3_slab_metrics.csv fig3_slab_bands.csv fig3_box_bands.csv fig3_dam_metrics.csv table1.csv; do
  [ -f "$R/$f" ] || { echo "bars.sh: $R/$f missing: run fig3.sh and table1.sh first" >&2; exit 2; }
done
# metric FILE VARIANT COLUMN: a column of metrics.csv for one variant (by name: lib.sh).
metric() { csv_awk -v v="$2" 'if (col("variant") == v) print col("'"$3"'")' "$1"; }
# band FILE NORMALS FILTER REGION: mean_deg of a bands row.
band() { awk -F, -v n="$2" -v f="filter=$3" -v r="$4" '$1 == n && $2 == f && $3 == r {print $5}' "$1"; }
# frame LABEL METHOD SIZE [STAGE]
frame() { awk -F, -v l="$1" -v m="$2" -v s="$3" -v st="${4:-frame}" '$1 == l && $3 == m && $4 == s && $5 == st {print $6}' "$R/table1.csv"; }
verdict() { awk "BEGIN {print ($1) ? \"pass\" : \"FAIL\"}"; }
B='normals=blend;normal_filter=on' Ba='normals=basic;normal_filter=on'
csv=$R/bars.csv
{
  echo "# $(csv_commit $R/fig3_slab_metrics.csv $R/fig3_slab_bands.csv $R/fig3_box_bands.csv $R/fig3_dam_metrics.csv $R/table1.csv); issue 4 bars, raycast_pca shipped defaults; from fig3_*.csv and table1.csv (llvmpipe)"
  echo "bar,measured,threshold,verdict,note"
  # 1. slab, harness interior mask (includes the rounded band along the slab's edges)
  b=$(metric $R/fig3_slab_metrics.csv "$B" interior_normal_mean_deg); a=$(metric $R/fig3_slab_metrics.csv "$Ba" interior_normal_mean_deg)
  echo "slab_interior_blend_deg (harness mask),$b,<= 2 and < basic $a,$(verdict "$b <= 2 && $b < $a"),interior = >= 3 px from silhouettes; keeps the 2r edge band"
  b=$(band $R/fig3_slab_bands.csv blend on face); a=$(band $R/fig3_slab_bands.csv basic on face)
  echo "slab_face_blend_deg (interior minus 2r edge band),$b,<= 2 and < basic $a,$(verdict "$b <= 2 && $b < $a"),the issue reports interior and edge band separately"
  b=$(band $R/fig3_slab_bands.csv blend on top); a=$(band $R/fig3_slab_bands.csv basic on top)
  echo "slab_top_face_blend_deg,$b,<= 2 and < basic $a,$(verdict "$b <= 2 && $b < $a"),top face >= 2r from its edges"
  # 2. box edge band
  b=$(band $R/fig3_box_bands.csv blend on edge_band); a=$(band $R/fig3_box_bands.csv basic on edge_band)
  echo "box_edge_band_blend_deg,$b,<= basic $a,$(verdict "$b <= $a"),pixels both cover within 2r of an ideal edge"
  b=$(band $R/fig3_box_bands.csv blend on edge_band_interior); a=$(band $R/fig3_box_bands.csv basic on edge_band_interior)
  echo "box_edge_band_interior_blend_deg,$b,<= basic $a,$(verdict "$b <= $a"),the same band inside the 3 px interior mask"
  # 3. dam break against reference
  iou=$(metric $R/fig3_dam_metrics.csv "$B" mask_iou); p95=$(metric $R/fig3_dam_metrics.csv "$B" depth_p95_r)
  echo "dam_break_iou,$iou,>= 0.97,$(verdict "$iou >= 0.97"),$(quick 512x512 128x128) against reference (same kernel and iso)"
  echo "dam_break_depth_p95_r,$p95,<= 0.1,$(verdict "$p95 <= 0.1"),error around the bias in r"
  # 4. speed at 1024^2
  for l in dam_break_24k $BOX; do
    f=$(frame $l raycast_pca $SPEED); ref=$(frame $l reference $SPEED)
    split=""
    for st in splat march normals filter thickness readback; do split="$split $st=$(frame $l raycast_pca $SPEED $st)"; done
    ratio=$(awk -v a="$ref" -v b="$f" 'BEGIN {if (a != "" && b > 0) printf "%.2f", a / b; else print "n/a"}')
    echo "speed_${l}_${SPEED}_ms,$f,report,measured,stages ms:$split; CPU reference $ref ms = ${ratio}x raycast_pca's frame"
  done
} > "$csv.tmp"
publish "$csv"
column -t -s, "$csv"
