#!/usr/bin/env bash
# scripts/check_quick.py, which experiments/run_all.sh --quick runs on the quick
# studies' CSVs (in CI, scripts/test.sh; not here: the studies take minutes):
#   its table covers every study of run_all.sh;
#   the committed full-size results/ meet the same bounds (they hold by definition at any
#   size; bench_make_splash writes under results/ nothing the table reads, so it is skipped);
#   it fails, naming the study, the CSV and the number, on a value out of its bound, on a
#   value that must be the same over rows and is not, on a switch that changes nothing, on a
#   bar's verdict that is not the committed one, and on a study without a row.
# usage: tests/check_quick.sh SRC OUT
set -u
SRC=$1 T=$2
rm -rf "$T"; mkdir -p "$T"; cd "$SRC" || exit 2
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
Q=(python3 scripts/check_quick.py)
"${Q[@]}" --table-only > "$T/table.txt" 2>&1; rc=$?
check '[ $rc -eq 0 ]' "every study of run_all.sh has a row ($(tr '\n' ' ' < "$T/table.txt" | head -c 600))"
"${Q[@]}" results --skip bench_make_splash > "$T/results.txt" 2>&1; rc=$?
check '[ $rc -eq 0 ]' "the committed results/ meet the bounds ($(tr '\n' ' ' < "$T/results.txt" | head -c 600))"
# the reference against itself with an IoU of 0.5
mkdir -p "$T/r/baselines" "$T/r/inacio2010"
{ echo "# commit=0; dirty=0"; echo "method,variant,reference,frame,mask_iou,depth_bias_r,depth_rmse_r,normal_mean_deg"
  echo "reference,,reference,,0.5,0,0,0"; } > "$T/r/baselines/quality.csv"
"${Q[@]}" "$T/r" --only baselines > "$T/iou.txt" 2>&1; rc=$?
cat "$T/iou.txt"
check '[ $rc -eq 1 ] && grep -q "^check_quick: FAIL baselines: $T/r/baselines/quality.csv: row .*: mask_iou = 0.5, want in \[1, 1\]" "$T/iou.txt"' \
  "a reference IoU of 0.5 against itself fails, naming the study, the CSV and the number"
# a simulation that loses a particle between frames
for p in cpu gpu; do
  { echo "frame,t,particles"; echo "0,0,1000"; echo "1,0.1,$([ $p = gpu ] && echo 999 || echo 1000)"; } > "$T/r/inacio2010/sim_bar_${p}_frames.csv"
done
echo "depth,depth_expected,depth_rel_err,clamps" > "$T/r/inacio2010/sim_bar.csv"; echo "0.2,0.2,0,0" >> "$T/r/inacio2010/sim_bar.csv"
"${Q[@]}" "$T/r" --only inacio2010_sim_bar > "$T/mass.txt" 2>&1; rc=$?
cat "$T/mass.txt"
check '[ $rc -eq 1 ] && [ "$(grep -c FAIL "$T/mass.txt")" -eq 1 ] && grep -q "FAIL inacio2010_sim_bar: .*sim_bar_gpu_frames.csv: particles differs over 2 rows: 999 .*1000" "$T/mass.txt"' \
  "a lost particle (mass not conserved) fails, naming the CSV and both counts"
# a bar whose verdict is not the committed one
mkdir -p "$T/r/xiao2017" "$T/r/xu2022"
sed 's/^dam_break_iou,\([^,]*\),\([^,]*\),pass,/dam_break_iou,\1,\2,FAIL,/' results/xiao2017/bars.csv > "$T/r/xiao2017/bars.csv"
"${Q[@]}" "$T/r" --only xiao2017_bars > "$T/bars.txt" 2>&1; rc=$?
cat "$T/bars.txt"
check '[ $rc -eq 1 ] && grep -q "FAIL xiao2017_bars: .*bars.csv: row bar=dam_break_iou.*: verdict is .FAIL., the committed results/xiao2017/bars.csv says .pass." "$T/bars.txt"' \
  "a bar whose verdict differs from the committed one fails, naming the bar and both verdicts"
# a switch that changes nothing: anisotropy on as rough as off
{ echo "scene,reference,anisotropy,mask_iou,normal_mean_deg,interior_normal_mean_deg,depth_rmse_r"
  echo "box,analytic,off,0.95,46.8,47.3,0.76"; echo "box,analytic,on,0.95,46.8,47.3,0.76"
  echo "dam,reference,off,0.87,44.7,44.6,4.2"; echo "dam,reference,on,0.87,25.4,24.6,4.0"; } > "$T/r/xu2022/fig2.csv"
"${Q[@]}" "$T/r" --only xu2022_fig2 > "$T/switch.txt" 2>&1; rc=$?
cat "$T/switch.txt"
check '[ $rc -eq 1 ] && [ "$(grep -c FAIL "$T/switch.txt")" -eq 1 ] && grep -q "FAIL xu2022_fig2: .*fig2.csv: row scene=box, reference=analytic, anisotropy=on: normal_mean_deg = 46.8, want below 0.8 x 46.8 (row scene=box" "$T/switch.txt"' \
  "an anisotropy switch that changes nothing fails, naming both rows"
# a study run_all.sh runs without a row in the table
cp experiments/run_all.sh "$T/run_all.sh"
echo "study brand_new bash experiments/brand_new.sh" >> "$T/run_all.sh"
"${Q[@]}" --table-only --run-all "$T/run_all.sh" > "$T/cover.txt" 2>&1; rc=$?
cat "$T/cover.txt"
check '[ $rc -eq 1 ] && grep -q "FAIL brand_new: a study of $T/run_all.sh without a row" "$T/cover.txt"' "a study without a row fails, naming it"
# a row for a study run_all.sh no longer runs
grep -v '^study demo ' experiments/run_all.sh > "$T/run_all_nodemo.sh"
"${Q[@]}" --table-only --run-all "$T/run_all_nodemo.sh" > "$T/stale.txt" 2>&1; rc=$?
check '[ $rc -eq 1 ] && grep -q "FAIL demo: a row .* for a study" "$T/stale.txt"' "a row for a study that no longer runs fails ($(head -c 200 "$T/stale.txt"))"
"${Q[@]}" --bogus > /dev/null 2>&1; rc=$?
check '[ $rc -eq 2 ]' "bad usage: exit 2"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
