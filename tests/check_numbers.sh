#!/usr/bin/env bash
# scripts/check_numbers.py beyond the committed files (the ctest results_numbers):
#   a wrong annotated number in docs/DESIGN.md fails, naming the line, the text's number and
#   the CSV's;
#   a time typed without a note in docs/DESIGN.md fails;
#   in an index verdict, an integer, a time and a number written out without a note fail, and a
#   paper's number, a setting and a parameter after = pass;
#   count, med, sum and the COL<N / COL>N conditions give what they should.
# usage: tests/check_numbers.sh SRC OUT
set -u
SRC=$1 T=$2
rm -rf "$T"; mkdir -p "$T/docs" "$T/r/results"; cd "$SRC" || exit 2
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
C=(python3 scripts/check_numbers.py)
ln -s "$SRC/results" "$T/results"
# DESIGN's fixed cost of an 8x8 render, 0.08 s in results/bench/speed.csv, typed as 0.17
sed 's/machine): 0\.08<!--n/machine): 0.17<!--n/' docs/DESIGN.md > "$T/docs/DESIGN.md"
"${C[@]}" "$T/docs/DESIGN.md" > "$T/wrong.txt" 2>&1; rc=$?
cat "$T/wrong.txt"
check '[ $rc -eq 1 ] && grep -q "DESIGN.md:[0-9]*: the text says 0.17, ../results/bench/speed.csv gives 0.08" "$T/wrong.txt"' \
  "a wrong number in docs/DESIGN.md fails, naming the text's number and the CSV's"
check 'grep -q "machine): 0.17<!--n" "$T/docs/DESIGN.md"' "(the edit took)"
sed 's/^## Start-up$/## Start-up\n\nA render takes 0.5 s./' docs/DESIGN.md > "$T/docs/DESIGN.md"
"${C[@]}" "$T/docs/DESIGN.md" > "$T/time.txt" 2>&1; rc=$?
check '[ $rc -eq 1 ] && grep -q "DESIGN.md:[0-9]*: 0.5 s has no <!--n" "$T/time.txt"' "a time without a note in docs/DESIGN.md fails ($(head -c 200 "$T/time.txt"))"
# an index of one row, its verdict citing a CSV of its own
{ echo "# commit=0; dirty=0"; echo "cell,ms,ok"; echo "a,10,1"; echo "b,30,0"; echo "c,20,1"; } > "$T/r/results/t.csv"
index() {
  { echo "| item | what | analogue | verdict | commit |"; echo "|---|---|---|---|---|"
    echo "| x Fig. 1 | claim | [t.csv](t.csv) | $1 | 0 |"; } > "$T/r/results/README.md"
  "${C[@]}" "$T/r/results/README.md" > "$T/index.txt" 2>&1
  rc=$?
}
N='<!--n t.csv'
index "**holds**: 2$N count[ok=1]ms %.0f--> of 3$N count[]ms %.0f--> cells, median 20$N med[]ms %.0f--> ms, total 60$N sum[]ms %.0f--> ms, 30$N max[ms>15&ms<35]ms %.0f--> at most"
check '[ $rc -eq 0 ]' "count, med, sum and COL<N / COL>N give what they should ($(tr '\n' ' ' < "$T/index.txt" | head -c 300))"
index "**holds**: 3$N count[ok=1]ms %.0f--> of 3 cells"
check '[ $rc -eq 1 ] && grep -q "the text says 3, t.csv gives 2" "$T/index.txt"' "a wrong count fails"
for bad in "in 2 of 3 cells" "in 12 ms" "a hundred times cheaper" "ten times faster" "by 1.5x"; do
  index "**partly holds**: $bad (t.csv)"
  check '[ $rc -eq 1 ] && grep -q "x Fig. 1: .* has no <!--n" "$T/index.txt"' "a verdict with '$bad' and no note fails"
done
index "**partly holds**: the paper's 12<!--paper--> ms and 88x<!--paper-->, a budget of 290<!--set--> s, with k = 0.998, in Fig. 5 and Table 1 at 512^2 with 30,000 particles"
check '[ $rc -eq 0 ]' "a paper's number, a setting, a parameter, references, sizes and counts pass ($(head -c 300 "$T/index.txt"))"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
