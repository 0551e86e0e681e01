#!/usr/bin/env bash
# Runs every libFuzzer target of tests/fuzz for SECONDS each (CI: 10, the smoke test),
# FS_FUZZ_JOBS (default 2) at a time: each libFuzzer process runs on one core.
# Builds them first into BUILD (tests/fuzz/build.sh; default build-fuzz: clang -O1, -DFS_FUZZ=ON,
# ASan + UBSan).
# Each target starts from its committed seeds (corpus_NAME/) plus what earlier runs
# found (out/fuzz/NAME/corpus, not committed); a crash, leak, hang (-timeout) or
# over-large allocation (-rss_limit_mb, -malloc_limit_mb) stops the target, keeps
# the input in out/fuzz/NAME/ and fails the run.
#   tests/fuzz/run.sh SECONDS [BUILD]
# FS_FUZZ_SEED=S (CI's smoke run, scripts/test.sh): each target first runs every committed
# regression file (regress_NAME/) once, then every seed (corpus_NAME/), and searches with
# libFuzzer's seed S from the seeds alone (a fresh corpus folder), for at most the runs that
# tests/fuzz/smoke_runs.txt lists for it, so CI repeats the start of the search that was
# checked clean when that list was written (a slower machine or fewer SECONDS stop earlier,
# on time). Unseeded runs and the campaigns (campaign.sh) explore anew each time and are the
# ones that find new inputs.
set -uo pipefail
cd "$(dirname "$0")/../.."
SECONDS_EACH=${1:?usage: tests/fuzz/run.sh SECONDS [BUILD]}
BUILD=${2:-build-fuzz}
bash tests/fuzz/build.sh "$BUILD" || exit 1
JOBS=${FS_FUZZ_JOBS:-2}
# run_target EXE: one target, its verdict in out/fuzz/NAME/verdict.txt
run_target() {
  local exe=$1 name=${1##*/fuzz_} out corpus dict args search=() cap rc runs regress=()
  out=out/fuzz/$name
  corpus=$out/corpus
  mkdir -p "$corpus"
  dict=tests/fuzz/$name.dict
  args=(-max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024
        -max_len=65536 -artifact_prefix="$out/" -print_final_stats=1)
  [ -f "$dict" ] && args+=(-dict="$dict")
  if [ -n "${FS_FUZZ_SEED:-}" ]; then
    corpus=$out/smoke_corpus
    rm -rf "$corpus"; mkdir -p "$corpus"
    search=(-seed="$FS_FUZZ_SEED")
    cap=$(awk -v n="$name" '$1 == n { print $2 }' tests/fuzz/smoke_runs.txt 2> /dev/null)
    [ -n "$cap" ] && search+=(-runs="$cap")
    [ -d "tests/fuzz/regress_$name" ] && regress=("tests/fuzz/regress_$name"/*)
  fi
  export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
  : > "$out/log.txt"
  rc=0
  # files (not folders) as arguments: libFuzzer runs each once (-runs=N would run each N times)
  [ ${#regress[@]} -eq 0 ] || "$exe" "${args[@]}" "${regress[@]}" >> "$out/log.txt" 2>&1 || rc=$?
  # the first corpus folder receives new inputs: keep the committed seeds untouched
  if [ $rc -eq 0 ]; then
    "$exe" "${args[@]}" "${search[@]}" "$corpus" "tests/fuzz/corpus_$name" >> "$out/log.txt" 2>&1 || rc=$?
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/log.txt" | tail -1)
  if [ $rc -eq 0 ]; then
    echo "fuzz $name: ok, ${runs:-?} runs in ${SECONDS_EACH} s" > "$out/verdict.txt"
  else
    { echo "fuzz $name: FAILED (exit $rc); input kept in $out/, log $out/log.txt:"
      grep -m3 -E "ERROR|SUMMARY|runtime error|fuzz:" "$out/log.txt" | sed 's/^/  /'; } > "$out/verdict.txt"
  fi
}
names=() running=0
for exe in "$BUILD"/tests/fuzz/fuzz_*; do
  [ -x "$exe" ] || continue
  name=${exe##*/fuzz_}
  # NAME_mut: the same harness with a custom mutator, for campaign.sh alone (the smoke
  # run's search stays the one smoke_runs.txt was checked with)
  case $name in *_mut) continue ;; esac
  names+=("$name")
  rm -f "out/fuzz/$name/verdict.txt"
  if [ "$running" -ge "$JOBS" ]; then wait -n; running=$((running - 1)); fi
  run_target "$exe" &
  running=$((running + 1))
done
wait
failed=()
for name in "${names[@]}"; do
  cat "out/fuzz/$name/verdict.txt" 2> /dev/null || echo "fuzz $name: FAILED (no verdict)"
  grep -q "^fuzz $name: ok" "out/fuzz/$name/verdict.txt" 2> /dev/null || failed+=("$name")
done
[ ${#failed[@]} -eq 0 ] || { echo "fuzz: ${#failed[@]} target(s) failed: ${failed[*]}" >&2; exit 1; }
