#!/usr/bin/env bash
# Peak memory per particle (issue 13, "Memory"): peak RSS of whole
# `fluidsurf render` processes at SIZE x SIZE (default 1024) for reference,
# spheres and raycast_pca on synthetic boxes of 97,336 (46^3) and 1,000,000
# (100^3) particles, plus any larger counts given as arguments (rounded down to
# a cube), and for spheres and raycast_pca also from a binary PLY file of the
# same boxes (a file reader's buffers count). Median of RUNS runs (default 3;
# REF_RUNS for the slow CPU reference, default RUNS; LARGE_METHODS picks the
# methods for the larger counts, default all).
#
# Usage: experiments/bench/memory.sh [N ...]   with STATE=before|after|... (default
# "current") naming the rows: results/bench/memory.csv keeps the rows of every
# other state, so a before/after pair stays side by side. Then
# experiments/bench/memory_table.sh regenerates the table in README-memory.md.
# FS_QUICK=1 (run_all.sh --quick): boxes of 16^3 and 30^3 at 128x128, 1 run, into
# out/quick/results/bench (work files in out/quick/bench/memory), then memory_table.sh
# on that CSV (into a copy of README-memory.md there).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, quick, RESULTS, study_commit
BIN=${BIN:-./build/fluidsurf}
RUNS=${RUNS:-$(quick 3 1)}
REF_RUNS=${REF_RUNS:-$RUNS}
SIZE=${SIZE:-$(quick 1024 128)}
STATE=${STATE:-current}
METHODS=${METHODS:-"reference spheres raycast_pca"}
FILE_METHODS=${FILE_METHODS:-"spheres raycast_pca"}
LARGE_METHODS=${LARGE_METHODS:-$METHODS} # for the counts given as arguments (the reference takes minutes a run)
OUT=$RESULTS/bench
TMP=$(quick out/bench/memory out/quick/bench/memory)
csv=$OUT/memory.csv
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "memory.sh: $BIN missing: build first (scripts/build.sh build)" >&2; exit 2; }
command -v python3 > /dev/null || { echo "memory.sh: needs python3 to write the PLY inputs" >&2; exit 2; }

# box SIDE: a synthetic scene of SIDE^3 particles (lattice 2r, jitter 0.1 r, seed 1).
box() {
  local side=$1 f=$TMP/box_$1.json
  printf '{"particles": {"synthetic": "box", "size": [%d, %d, %d], "jitter": 0.1, "seed": 1}, "radius": 0.025}\n' \
    "$side" "$side" "$side" > "$f"
  echo "$f"
}

# ply SIDE: the same lattice (without jitter) as a binary little-endian PLY file.
ply() {
  local side=$1 f=$TMP/box_$1.ply
  [ -s "$f" ] || python3 - "$side" "$f" <<'PY'
import struct, sys
n, path = int(sys.argv[1]), sys.argv[2]
d = 0.05
with open(path + ".tmp", "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\ncomment radius 0.025\n")
    f.write(b"element vertex %d\nproperty float x\nproperty float y\nproperty float z\nend_header\n" % n**3)
    row = struct.Struct("<%df" % (3 * n))
    for k in range(n):
        for j in range(n):
            f.write(row.pack(*[v for i in range(n) for v in (d * i, d * j + 0.025, d * k)]))
import os; os.replace(path + ".tmp", path)
PY
  echo "$f"
}

# measure INPUT_KIND N METHOD INPUT: RUNS whole-process peak RSS values, the median row.
measure() {
  local kind=$1 n=$2 method=$3 input=$4 runs=$RUNS
  [ "$method" = reference ] && runs=$REF_RUNS
  local f=$TMP/${kind}_${n}_${method}.kib
  : > "$f"
  for i in $(seq "$runs"); do
    /usr/bin/time -f "%M" -o "$f.one" "$BIN" render "$input" --method "$method" -W "$SIZE" -H "$SIZE" -q \
      -o "$TMP/last.png"
    cat "$f.one" >> "$f"
  done
  local med lo hi
  med=$(median < "$f"); lo=$(sort -g "$f" | head -1); hi=$(sort -g "$f" | tail -1)
  echo "$STATE,$kind,$method,$n,$SIZE,$runs,$med,$lo,$hi,$commit" >> "$csv.rows"
  printf '%-7s %-9s %-12s %9d  peak %8s KiB (min %s, max %s, %d runs)\n' "$STATE" "$kind" "$method" "$n" "$med" "$lo" "$hi" "$runs"
}

# the provenance: study_commit in the state's header line; each row's commit column names the
# same commit, with -dirty when study_commit says dirty=1
provenance=$STUDY_PROV
commit=$(sed 's/^commit=\([^;]*\);.*/\1/' <<< "$provenance")
case $provenance in *dirty=1) commit=$commit-dirty ;; esac
sides=$(quick "46 100" "16 30")
for n in "$@"; do sides="$sides $(python3 -c "import sys; print(int(round(int(sys.argv[1]) ** (1/3))))" "$n")"; done
: > "$csv.rows"
for side in $sides; do
  n=$((side * side * side)) methods=$METHODS
  [ "$side" -gt 100 ] && methods=$LARGE_METHODS
  for m in $methods; do measure synthetic "$n" "$m" "$(box "$side")"; done
  for m in $FILE_METHODS; do measure ply "$n" "$m" "$(ply "$side")"; done
done

# Keep the other states' rows and header lines; replace this state's. The first line names
# this run's commit and, as sources=, the kept states' (check_results.sh)
kept_sources() {
  [ -f "$csv" ] || return 0
  local s
  s=$(grep '^# state ' "$csv" | grep -v "^# state $STATE:" | sed -E 's/^# state ([^:]*):.*commit[= ]([0-9a-f]+)(; dirty=([01]))?.*/state_\1@\2:dirty=\4/; s/:dirty=$/:dirty=unknown/' | paste -sd,)
  [ -z "$s" ] || echo "; sources=state_$STATE@$(sed 's/commit=\([^;]*\); dirty=\(.\)/\1:dirty=\2/' <<< "$provenance"),$s"
}
header="# state $STATE: $provenance; $(date -u +%Y-%m-%dT%H:%MZ); $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $("$BIN" --version 2>/dev/null | head -1)"
{
  echo "# $provenance$(kept_sources); fluidsurf peak memory benchmark (experiments/bench/memory.sh): peak RSS (/usr/bin/time %M, KiB) of whole 'fluidsurf render' processes"
  echo "# inputs: synthetic = box of n particles from a scene JSON; ply = the same lattice read from a binary PLY file; median/min/max over runs"
  [ -f "$csv" ] && grep '^# state ' "$csv" | grep -v "^# state $STATE:" || true
  echo "$header"
  echo "state,input,method,n,size,runs,peak_rss_kib_median,peak_rss_kib_min,peak_rss_kib_max,commit"
  [ -f "$csv" ] && grep -v '^#' "$csv" | grep -v '^state,' | awk -F, -v s="$STATE" '$1 != s' || true
  cat "$csv.rows"
} > "$csv.tmp"
publish "$csv"
rm -f "$csv.rows"
echo "wrote $csv"
# quick mode: the table too (memory_table.sh writes it beside this CSV, never into results/)
if [ "$FS_QUICK" = 1 ]; then bash experiments/bench/memory_table.sh; fi
