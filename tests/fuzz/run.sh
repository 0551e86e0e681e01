#!/usr/bin/env bash
# Runs every libFuzzer target of tests/fuzz for SECONDS each (CI: 30, the smoke test).
# Builds them first into BUILD (tests/fuzz/build.sh; default build-fuzz: clang -O1, -DFS_FUZZ=ON,
# ASan + UBSan).
# Each target starts from its committed seeds (corpus_NAME/) plus what earlier runs
# found (out/fuzz/NAME/corpus, not committed); a crash, leak, hang (-timeout) or
# over-large allocation (-rss_limit_mb, -malloc_limit_mb) stops the target, keeps
# the input in out/fuzz/NAME/ and fails the run.
#   tests/fuzz/run.sh SECONDS [BUILD]
# FS_FUZZ_SEED=S (CI's smoke run, scripts/test.sh): each target searches with libFuzzer's
# seed S from the committed seeds alone (a fresh corpus folder), for at most the runs that
# tests/fuzz/smoke_runs.txt lists for it, so CI repeats the search that was checked clean
# when that list was written (a slower machine stops earlier, on time). Unseeded runs
# explore anew each time and are the ones that find new inputs.
set -uo pipefail
cd "$(dirname "$0")/../.."
SECONDS_EACH=${1:?usage: tests/fuzz/run.sh SECONDS [BUILD]}
BUILD=${2:-build-fuzz}
bash tests/fuzz/build.sh "$BUILD" || exit 1
failed=()
for exe in "$BUILD"/tests/fuzz/fuzz_*; do
  [ -x "$exe" ] || continue
  name=${exe##*/fuzz_}
  # NAME_mut: the same harness with a custom mutator, for campaign.sh alone (the smoke
  # run's search stays the one smoke_runs.txt was checked with)
  case $name in *_mut) continue ;; esac
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
    args+=(-seed="$FS_FUZZ_SEED")
    cap=$(awk -v n="$name" '$1 == n { print $2 }' tests/fuzz/smoke_runs.txt 2> /dev/null)
    [ -n "$cap" ] && args+=(-runs="$cap")
  fi
  # the first corpus folder receives new inputs: keep the committed seeds untouched
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp \
    "$exe" "${args[@]}" "$corpus" "tests/fuzz/corpus_$name" > "$out/log.txt" 2>&1
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/log.txt")
  if [ $rc -eq 0 ]; then
    echo "fuzz $name: ok, ${runs:-?} runs in ${SECONDS_EACH} s"
  else
    echo "fuzz $name: FAILED (exit $rc); input kept in $out/, log $out/log.txt:"
    grep -m3 -E "ERROR|SUMMARY|runtime error|fuzz:" "$out/log.txt" | sed 's/^/  /'
    failed+=("$name")
  fi
done
[ ${#failed[@]} -eq 0 ] || { echo "fuzz: ${#failed[@]} target(s) failed: ${failed[*]}" >&2; exit 1; }
