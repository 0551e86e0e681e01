#!/usr/bin/env bash
# Every generated table in a committed Markdown file (<!-- table: CSV -->, written by
# experiments/tools/csv_table.py) equals what its CSV gives now: a README's numbers
# are the CSVs', never typed and never stale. Fails naming each stale block.
set -u
SRC=$1
cd "$SRC" || exit 2
files=$(grep -rl --include='*.md' -e '<!-- table: ' --exclude-dir='build*' --exclude-dir=out --exclude-dir=.git . | sort)
[ -n "$files" ] || { echo "FAIL no generated table found"; exit 1; }
fails=0
for f in $files; do
  if python3 experiments/tools/csv_table.py --check "$f"; then echo "ok   $f"; else echo "FAIL $f"; fails=$((fails + 1)); fi
done
[ $fails -eq 0 ] && echo "all passed" || { echo "$fails stale"; exit 1; }
