#!/usr/bin/env bash
# A fuzzing campaign (tests/fuzz/README.md, "Campaigns"): every libFuzzer target of
# tests/fuzz, unseeded, for MINUTES each, FS_FUZZ_JOBS (default 2) at a time, built into
# BUILD (tests/fuzz/build.sh; default build-fuzz, ASan + UBSan).
#   tests/fuzz/campaign.sh MINUTES [BUILD]
# Each target NAME searches a scratch copy of its committed seeds (corpus_NAME/) plus what
# earlier campaigns kept (out/fuzz-campaign/NAME/kept); NAME_mut is the same harness with
# its custom mutator (scene_mutator.c, vtu_mutator.c), from the same corpus, so the two
# rows say whether the mutator grows coverage. A crash, leak, hang over 10 s, more than
# 2 GB resident or an allocation over 1 GB stops a target and its input stays in
# out/fuzz-campaign/NAME/ (crash-*, leak-*, timeout-*, oom-*). Findings of earlier
# campaigns are replayed first: those that no longer fail move to NAME/fixed/, the rest
# count as open_findings. Afterwards each reader's new inputs that add coverage are
# merged (-merge=1) into its kept folder.
# Writes $RESULTS/fuzz/campaign.csv (target,minutes,runs,features,corpus_size,open_findings
# after a '#' provenance line: commit, dirty, settings) and its README.md
# (tests/fuzz/campaign_report.sh). RESULTS is results/ (FS_RESULTS overrides it); with
# FS_FUZZ_TARGETS="ply scene scene_mut" (a trial on some targets) the default is
# out/fuzz-campaign/results, so a partial run never replaces the committed table.
# Runs at the priority it is started with (nice -n 19 tests/fuzz/campaign.sh 10).
set -uo pipefail
cd "$(dirname "$0")/../.."
MINUTES=${1:?usage: tests/fuzz/campaign.sh MINUTES [BUILD]}
BUILD=${2:-build-fuzz}
[[ $MINUTES =~ ^[1-9][0-9]*$ ]] || { echo "campaign.sh: MINUTES must be a whole number of minutes > 0, not '$MINUTES'" >&2; exit 2; }
JOBS=${FS_FUZZ_JOBS:-2}
[ -n "${FS_FUZZ_TARGETS:-}" ] && [ -z "${FS_RESULTS:-}" ] && export FS_RESULTS=out/fuzz-campaign/results
source experiments/lib.sh # STUDY_PROV (taken now, before the run), RESULTS
OUT=out/fuzz-campaign
bash tests/fuzz/build.sh "$BUILD" || exit 1

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
LIMITS=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=65536)

targets=()
for exe in "$BUILD"/tests/fuzz/fuzz_*; do
  [ -x "$exe" ] && targets+=("${exe##*/fuzz_}")
done
if [ -n "${FS_FUZZ_TARGETS:-}" ]; then
  for t in $FS_FUZZ_TARGETS; do
    [ -x "$BUILD/tests/fuzz/fuzz_$t" ] || { echo "campaign.sh: FS_FUZZ_TARGETS names '$t', which $BUILD/tests/fuzz has no fuzz_$t for" >&2; exit 2; }
  done
  read -ra targets <<< "$FS_FUZZ_TARGETS"
fi
base() { echo "${1%_mut}"; } # the reader a target tests: its seeds, dictionary, kept inputs
findings() { find "$OUT/$1" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | sort; }

# Earlier findings: replayed once; what passes now was fixed. The VDB and VTU readers
# run the library in a child (read_in_child.c), where a crash is contained and not a
# finding, but libFuzzer's malloc limit still holds: an allocation over it ends the
# child with libFuzzer's out-of-memory report (and an oom-* file), while the target
# itself passes. So the child's stderr is kept and that report fails the replay too
# (unsymbolized: only pass or fail is read, and symbolizing OpenVDB's contained reports
# took seconds a file).
still_fails() {
  local log
  log=$(ASAN_OPTIONS=$ASAN_OPTIONS:symbolize=0 FLUIDSURF_CHILD_STDERR=1 "$BUILD/tests/fuzz/fuzz_$1" "${LIMITS[@]}" "$2" 2>&1) || return 0
  grep -q "ERROR: libFuzzer:" <<< "$log"
}
for t in "${targets[@]}"; do
  mkdir -p "$OUT/$t"
  for f in $(findings "$t"); do
    if ! still_fails "$t" "$f"; then
      mkdir -p "$OUT/$t/fixed"; mv "$f" "$OUT/$t/fixed/"
      echo "fuzz $t: ${f##*/} passes now (moved to $OUT/$t/fixed/)"
    fi
  done
done

# run_target NAME: one unseeded search in NAME/scratch; the log in NAME/log.txt
run_target() {
  local t=$1 b; b=$(base "$1")
  local dir=$OUT/$t scratch=$OUT/$t/scratch
  rm -rf "$scratch"; mkdir -p "$scratch" "$OUT/$b/kept"
  cp tests/fuzz/corpus_"$b"/* "$scratch/"
  cp -r "$OUT/$b/kept/." "$scratch/"
  local args=("${LIMITS[@]}" -max_total_time=$((MINUTES * 60)) -artifact_prefix="$dir/" -print_final_stats=1)
  [ -f "tests/fuzz/$b.dict" ] && args+=(-dict="tests/fuzz/$b.dict")
  "$BUILD/tests/fuzz/fuzz_$t" "${args[@]}" "$scratch" > "$dir/log.txt" 2>&1
  echo $? > "$dir/rc"
}

echo "fuzz campaign: ${#targets[@]} targets, $MINUTES min each, $JOBS at a time (about $(( (${#targets[@]} + JOBS - 1) / JOBS * MINUTES )) min)"
running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$JOBS" ]; then wait -n; running=$((running - 1)); fi
  run_target "$t" &
  running=$((running + 1))
done
wait

# stats NAME: "runs,features,corpus_size" from libFuzzer's final lines (the last status
# line's ft: and corp:)
stats() {
  local log=$OUT/$1/log.txt
  local runs; runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  local last; last=$(grep -E '^#[0-9]+.*ft: [0-9]+' "$log" | tail -1)
  local ft; ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$last")
  local corp; corp=$(sed -n 's/.* corp: \([0-9]*\)\/.*/\1/p' <<< "$last")
  echo "${runs:-0},${ft:-0},${corp:-0}"
}

csv=$RESULTS/fuzz/campaign.csv
mkdir -p "$RESULTS/fuzz"
{
  echo "# $STUDY_PROV; tests/fuzz/campaign.sh $MINUTES: unseeded libFuzzer ($(clang --version | head -1)), ASan + UBSan, $JOBS at a time, ${LIMITS[*]}"
  echo "target,minutes,runs,features,corpus_size,open_findings"
  for t in "${targets[@]}"; do
    echo "$t,$MINUTES,$(stats "$t"),$(findings "$t" | wc -l)"
  done
} > "$csv.tmp" && mv "$csv.tmp" "$csv"
failed=0
for t in "${targets[@]}"; do
  rc=$(cat "$OUT/$t/rc" 2> /dev/null || echo "?")
  if [ "$rc" = 0 ]; then
    echo "fuzz $t: ok ($(stats "$t") runs,features,corpus)"
  else
    failed=1
    echo "fuzz $t: FAILED (exit $rc); input kept in $OUT/$t/, log $OUT/$t/log.txt:"
    grep -m3 -E "ERROR|SUMMARY|runtime error|fuzz:" "$OUT/$t/log.txt" | sed 's/^/  /'
  fi
done

# The new inputs that add coverage join the reader's kept folder: merged into a copy of
# the committed seeds (named seed-*, dropped afterwards) and what was kept before
for b in $(for t in "${targets[@]}"; do base "$t"; done | sort -u); do
  merged=$OUT/$b/merge.tmp
  rm -rf "$merged"; mkdir -p "$merged"
  for f in tests/fuzz/corpus_"$b"/*; do cp "$f" "$merged/seed-${f##*/}"; done
  cp -r "$OUT/$b/kept/." "$merged/"
  before=$(find "$merged" -type f | wc -l)
  scratches=()
  for t in "${targets[@]}"; do [ "$(base "$t")" = "$b" ] && scratches+=("$OUT/$t/scratch"); done
  "$BUILD/tests/fuzz/fuzz_$b" "${LIMITS[@]}" -merge=1 -artifact_prefix="$merged/" "$merged" "${scratches[@]}" > "$OUT/$b/merge.log" 2>&1 ||
    { echo "fuzz $b: the merge failed ($OUT/$b/merge.log); $OUT/$b/kept unchanged" >&2; failed=1; continue; }
  echo "fuzz $b: $(( $(find "$merged" -type f | wc -l) - before )) new inputs kept in $OUT/$b/kept"
  rm -f "$merged"/seed-* "$merged"/crash-* "$merged"/leak-* "$merged"/timeout-* "$merged"/oom-*
  rm -rf "$OUT/$b/kept"; mv "$merged" "$OUT/$b/kept"
done

bash tests/fuzz/campaign_report.sh "$csv" || failed=1
echo "wrote $csv and $RESULTS/fuzz/README.md"
exit $failed
