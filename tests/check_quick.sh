#!/usr/bin/env bash
# experiments/tools/check_quick.py, which experiments/run_all.sh --quick runs on the quick
# studies' CSVs (in CI, scripts/test.sh; not here: the studies take minutes):
#   its table covers every study of run_all.sh;
#   the committed full-size results/ meet the same bounds (they hold by definition at any
#   size; bench_make_splash writes under results/ nothing the table reads, so it is skipped);
#   it fails, naming the study, the CSV and the number, on a value out of its bound, on a
#   value that must be the same over rows and is not, and on a study without a row.
# usage: tests/check_quick.sh SRC OUT
set -u
SRC=$1 T=$2
rm -rf "$T"; mkdir -p "$T"; cd "$SRC" || exit 2
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
Q=(python3 experiments/tools/check_quick.py)
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
echo "depth,depth_expected,depth_rel_err" > "$T/r/inacio2010/sim_bar.csv"; echo "0.2,0.2,0" >> "$T/r/inacio2010/sim_bar.csv"
"${Q[@]}" "$T/r" --only inacio2010_sim_bar > "$T/mass.txt" 2>&1; rc=$?
cat "$T/mass.txt"
check '[ $rc -eq 1 ] && [ "$(grep -c FAIL "$T/mass.txt")" -eq 1 ] && grep -q "FAIL inacio2010_sim_bar: .*sim_bar_gpu_frames.csv: particles differs over 2 rows: 999 .*1000" "$T/mass.txt"' \
  "a lost particle (mass not conserved) fails, naming the CSV and both counts"
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
