#!/usr/bin/env bash
# The main job on a fresh machine (issue 53): `bash scripts/demo.sh` in a fresh clone of
# COMMIT, with no compiler cache (CCACHE_DISABLE=1: the launcher scripts/build.sh adds
# where ccache is installed then runs the compiler itself, as on a machine without it)
# and the Debian packages already installed (scripts/setup.sh then does nothing). Times
# the whole script (the build and the demo's compare at its defaults) and counts the
# object files it compiled; appends a row to results/demo/fresh_time.csv:
# commit,objects_built,wall_s,user_s,sys_s,cpu_s.
# cpu_s (user + sys) barely moves with the machine's load; wall_s needs a quiet machine
# (experiments run under /work/bin/quiet where one is kept; otherwise cpu_s is the number).
#
#   experiments/demo/fresh_time.sh COMMIT    e.g. the commit before and the one after a change
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS, stamp_csv
commit=$(git rev-parse --short=10 "${1:?usage: fresh_time.sh COMMIT}")
OUT=$RESULTS/demo
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"
git clone -q --no-checkout . "$T/clone" && git -C "$T/clone" checkout -q "$commit"
( cd "$T/clone" && CCACHE_DISABLE=1 /usr/bin/time -f '%e %U %S' -o "$T/time" bash scripts/demo.sh > "$T/demo.log" 2>&1 ) ||
  { tail -20 "$T/demo.log" >&2; exit 1; }
built=$(find "$T/clone/build" -name '*.o' | wc -l)
read -r wall user sys < "$T/time"
csv=$OUT/fresh_time.csv
if [ ! -f "$csv" ]; then
  echo "# scripts/demo.sh in a fresh clone without a compiler cache, $(nproc) cores; seconds of the whole script" > "$csv"
  echo "commit,objects_built,wall_s,user_s,sys_s,cpu_s" >> "$csv"
  stamp_csv "$csv"
fi
printf '%s,%s,%s,%s,%s,%.2f\n' "$commit" "$built" "$wall" "$user" "$sys" "$(echo "$user + $sys" | bc -l)" >> "$csv"
tail -1 "$csv"
