#!/usr/bin/env bash
# Work counters end to end (docs/DESIGN.md, "Work counters"): render --counters
# gives the same counts for every method on OSMesa and EGL and on 1 and 2
# threads; compare --counters writes counters.csv and a table in report.md;
# the reference cache carries the counts (a hit brings them back, an entry made
# without them is a miss when they are wanted). A build without OSMesa (the lean
# build; FS_NO_OSMESA=1) compares EGL with 1 and 2 threads, and two EGL runs
# (a repeatability check) in place of OSMesa against EGL.
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
cube=$SRC/experiments/data/splashsurf/dam_break_frame_9_6859_particles.bgeo # every build reads BGEO
ctx=osmesa
[ "${FS_NO_OSMESA:-0}" = 1 ] && ctx=egl
box=$SRC/experiments/scenes/box.json
# counts NAME GL THREADS METHOD: the CSV rows (no provenance line) of one counting render;
# the status is fluidsurf's, not grep's
counts() {
  OMP_NUM_THREADS=$3 LP_NUM_THREADS=$3 FLUIDSURF_GL=$2 "$BIN" render "$cube" --method $4 -W 64 -H 48 -q --counters \
    -o "$T/$1.png" 2> "$T/$1.err" > "$T/$1.out"
  local rc=$?
  grep -v '^#' "$T/$1.out" > "$T/$1.csv"
  return $rc
}
# without OSMesa the second context is EGL again: a repeatability check
if [ $ctx = egl ]; then same_ctx="the same counts on two EGL runs (no OSMesa in this build)"
else same_ctx="the same counts on OSMesa and EGL"; fi
header='method,variant,frame,stage,counter,value'

# 1. the same counts on every context and thread count
all="spheres reference raycast_pca aniso_ssf surfels volume_raycast"
"$BIN" methods | grep -q '^levelset ' && all="$all levelset" # a build with OpenVDB
for m in ${METHODS:-$all}; do
  counts "$m-${ctx}2" $ctx 2 $m; rc=$?
  counts "$m-${ctx}1" $ctx 1 $m; rc1=$?
  counts "$m-egl2b" egl 2 $m; rc2=$?
  check '[ $rc -eq 0 ] && [ "$(head -1 "$T/$m-${ctx}2.csv")" = "$header" ] && grep -q "^$m,,0,total," "$T/$m-${ctx}2.csv"' \
    "$m: render --counters prints the CSV with total rows"
  check '! grep -q "^$m,,0,[a-z_]*,[a-z_]*,0$" <(grep -v ",total," "$T/$m-${ctx}2.csv")' "$m: zero counts are left out"
  check '[ $rc1 -eq 0 ] && cmp -s "$T/$m-${ctx}2.csv" "$T/$m-${ctx}1.csv"' "$m: the same counts on 1 and 2 threads"
  check '[ $rc2 -eq 0 ] && cmp -s "$T/$m-${ctx}2.csv" "$T/$m-egl2b.csv"' "$m: $same_ctx"
done
"$BIN" render "$cube" --method spheres -W 64 -H 48 -q --counters --timings -o "$T/both.png" > "$T/both.txt"
check 'grep -q "^stage,ms,gpu_ms,renderer" "$T/both.txt" && grep -q "^# .*method=spheres" "$T/both.txt" && grep -q "^$header" "$T/both.txt"' \
  "--timings and --counters together: both tables, the counts under a provenance line"

# 2. compare --counters: counters.csv with the provenance line, a table in report.md
"$BIN" compare "$box" --methods spheres,raycast_pca -W 64 -H 64 --repeat 1 -q --no-cache --counters -o "$T/cmp" 2> "$T/cmp.err"; rc=$?
check '[ $rc -eq 0 ] && head -1 "$T/cmp/counters.csv" | grep -q "^# .*commit=" && sed -n 2p "$T/cmp/counters.csv" | grep -qx "$header"' \
  "compare writes counters.csv with a provenance line and the header"
check 'grep -q "^reference,ground truth,0,march,march_samples,[1-9]" "$T/cmp/counters.csv" && grep -q "^raycast_pca,,0,filter,filter_taps,[1-9]" "$T/cmp/counters.csv"' \
  "counters.csv holds the reference's and the methods' counts"
check 'grep -q "^## Work counters" "$T/cmp/report.md" && grep -q "^| spheres | — | — | — | — | [1-9]" "$T/cmp/report.md"' \
  "report.md has the counter table"
"$BIN" compare "$box" --methods spheres -W 64 -H 64 --repeat 1 -q --no-cache -o "$T/plain" 2> /dev/null
check '[ ! -e "$T/plain/counters.csv" ] && ! grep -q "Work counters" "$T/plain/report.md"' "without --counters: no counters.csv"
# the counting render is outside every timed span: the reference's time (the panel's caption is
# its timings.csv total) has the same stages with and without --counters, and no other
gt_stages() { grep '^reference,ground truth,' "$T/$1/timings.csv" | cut -d, -f3 | tr '\n' ' '; }
check '[ -n "$(gt_stages cmp)" ] && [ "$(gt_stages cmp)" = "$(gt_stages plain)" ]' \
  "compare --counters adds no stage to the reference's timings ($(gt_stages cmp))"

# 3. the reference cache carries the counts
ref_rows() { grep '^reference,ground truth,' "$T/$1/counters.csv"; }
cmpc() { local d=$1; shift; "$BIN" compare "$box" --methods spheres -W 64 -H 64 --repeat 1 -q -o "$T/$d" "$@" 2> "$T/$d.err"; }
cmpc c1 --cache "$T/cache" --counters
cmpc c2 --cache "$T/cache" --counters
check 'grep -q "rendered, stored as" "$T/c1/report.md" && grep -q "from the cache:" "$T/c2/report.md"' "a counted entry is stored, then hit"
check '[ -n "$(ref_rows c1)" ] && [ "$(ref_rows c1)" = "$(ref_rows c2)" ]' "a hit brings back the counts it was stored with"
cmpc u1 --cache "$T/cache2"
cmpc u0 --cache "$T/cache2"
cmpc u2 --cache "$T/cache2" --counters
cmpc u3 --cache "$T/cache2" --counters
check 'grep -q "rendered, stored as" "$T/u1/report.md" && grep -q "from the cache:" "$T/u0/report.md"' "an entry made without counts is a hit without --counters"
check 'grep -q "rendered, stored as" "$T/u2/report.md" && [ -n "$(ref_rows u2)" ]' "an entry without counts is a miss with --counters, counted and stored"
check 'grep -q "from the cache:" "$T/u3/report.md" && [ "$(ref_rows u2)" = "$(ref_rows u3)" ] && [ "$(ref_rows u2)" = "$(ref_rows c1)" ]' \
  "the re-stored entry then hits with the same counts"
for k in 1 2; do
  "$BIN" render "$box" -W 64 -H 64 --cache "$T/cache3" --counters -o "$T/r$k.png" 2> "$T/r$k.err" | grep -v '^#' > "$T/r$k.csv"
done
check 'grep -q "^reference,,0,march,march_samples,[1-9]" "$T/r1.csv" && grep -q "from the cache" "$T/r2.err" && cmp -s "$T/r1.csv" "$T/r2.csv"' \
  "render --cache --counters stores the counts and prints them again from the entry"

echo "$fails failure(s)"
[ $fails -eq 0 ]
