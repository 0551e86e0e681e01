#!/usr/bin/env bash
# Joins the folder of the study's second device call into the first's (experiments/gpu/README.md,
# "Two calls"): the second call's step CSVs, repeat/, check/, images/, demo/ and logs/ go beside
# the first's, its status.csv rows are appended to the first's, and the first's env.csv stays
# (the machine of the timing tables; repeat/env.csv records the second call's). Refuses when
# the two name different commits (the pack's provenance) or a step CSV is in both.
# usage: experiments/gpu/merge.sh FIRST SECOND   (then: report.py FIRST > FIRST/README.md)
set -euo pipefail
[ $# = 2 ] && [ -f "$1/status.csv" ] && [ -f "$2/status.csv" ] ||
  { echo "merge.sh: usage: merge.sh FIRST SECOND (two run.sh folders with status.csv)" >&2; exit 2; }
a=$1 b=$2
prov() { head -1 "$1/status.csv" | sed 's/^# experiments\/gpu\/run.sh; //'; }
[ "$(prov "$a")" = "$(prov "$b")" ] ||
  { echo "merge.sh: $a ($(prov "$a")) and $b ($(prov "$b")) were made at different commits" >&2; exit 2; }
for f in "$b"/*.csv; do
  n=$(basename "$f")
  case $n in env.csv | status.csv | tables.csv) continue ;; esac
  [ ! -e "$a/$n" ] || { echo "merge.sh: $n is in both $a and $b" >&2; exit 2; }
done
for f in "$b"/*.csv; do
  case $(basename "$f") in env.csv | status.csv | tables.csv) ;; *) cp "$f" "$a/" ;; esac
done
for d in repeat check images demo logs; do
  [ -d "$b/$d" ] && mkdir -p "$a/$d" && cp -r "$b/$d/." "$a/$d/"
done
grep -v '^#' "$b/status.csv" | tail -n +2 >> "$a/status.csv"
echo "merge.sh: $b joined into $a"
