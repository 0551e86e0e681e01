#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite. First the C style check
# (scripts/check_format.sh, .clang-format); then the normal build and its ctest, and
# experiments/run_all.sh --quick (every study script at small sizes); then the lean build
# (scripts/build_lean.sh: no VTK, OpenVDB, OpenImageIO, GLFW, OSMesa) with its own tests on
# EGL, and every method rendered by both builds compared (tests/lean_vs_full.sh); then the
# suite once more under AddressSanitizer + UndefinedBehaviorSanitizer (suppressions only for
# Mesa/LLVM and two libraries' error paths, tests/lsan.supp), which also replays the fuzz
# seeds and regression files (tests/fuzz); and last every libFuzzer target of tests/fuzz
# (clang, ASan + UBSan: tests/fuzz/run.sh), its seeds and regression files, then 10 s of
# seeded search. Set FS_NO_SANITIZE=1 to skip the last two. The lean, sanitizer and fuzz
# builds run behind the normal ctest and the studies (builds_behind below).
#
#   scripts/test.sh                 the whole suite (README's test command, CI's)
#   scripts/test.sh --quick         a developer's loop: the style check, the normal build
#                                   (incremental) and its ctest without the tests labelled
#                                   `long` (tests/CMakeLists.txt)
#   scripts/test.sh --only S1,S2    only these stages (names below), in the suite's order,
#                                   on the builds earlier stages left
# Each stage's wall and CPU seconds go to out/test_times/stage_NAME.csv and each ctest's own
# per-test times to out/test_times/NAME.xml (JUnit); experiments/bench/test_times.sh turns
# them into results/bench/test_times.csv. A stage past its budget (below) prints a line.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0 only=""
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1 ;;
    --only) only=${2:?--only needs a list of stages}; shift ;;
    *) echo "usage: scripts/test.sh [--quick] [--only STAGE,...]" >&2; exit 2 ;;
  esac
  shift
done
TIMES=$PWD/out/test_times
mkdir -p "$TIMES"
exec 3>&1 # each stage's end, also from the builds behind (whose own output goes to a log)
HZ=$(getconf CLK_TCK)
# the commit the stages run at, and whether the tree differs from it (as experiments/lib.sh)
made="$(git rev-parse --short=10 HEAD 2> /dev/null || echo unknown),$(git diff --quiet HEAD -- . ':!results' 2> /dev/null && echo 0 || echo 1)"
# cpu_ticks PID: the user + system ticks of shell PID and of every child it has waited for
cpu_ticks() { awk '{ print $14 + $15 + $16 + $17 }' "/proc/$1/stat"; }
# Each stage's budget in seconds: along the path the run waits on (setup, format, build,
# the longer of ctest and studies, builds_wait, lean_ctest, asan_ctest, fuzz) together 40
# minutes, CI's limit being 90; the builds behind have none of their own (builds_wait is
# what they cost). A stage that takes longer prints a line, and the run's last lines
# repeat it, so growth is seen before it fails a landing.
declare -A budget=([setup]=30 [format]=30 [build]=360 [ctest]=600 [studies]=600 [builds_wait]=300
  [lean_ctest]=180 [asan_ctest]=540 [fuzz]=120 [ctest_quick]=420)
: > "$TIMES/over_budget.txt"
# stage NAME COMMAND...: runs one stage (unless --only leaves it out) and prints its end:
# seconds since the start, its own wall and CPU seconds, the disk this checkout takes and
# the disk left (a CI run once ran out of disk)
stage() {
  local name=$1 t0=$SECONDS me=$BASHPID c0 wall cpu
  shift
  [ -z "$only" ] || [[ ,$only, == *,$name,* ]] || return 0
  c0=$(cpu_ticks "$me")
  "$@"
  wall=$((SECONDS - t0)) cpu=$((($(cpu_ticks "$me") - c0) / HZ))
  echo "$name,$wall,$cpu,${budget[$name]:-},$made" > "$TIMES/stage_$name.csv"
  echo >&3 "== test.sh: $name done at ${SECONDS} s ($wall s, CPU $cpu s); $(du -sm . | cut -f1) MB here, $(df -Pm . | awk 'NR == 2 {print $4}') MB free"
  if [ -n "${budget[$name]:-}" ] && [ "$wall" -gt "${budget[$name]}" ]; then
    echo "== test.sh: OVER BUDGET: $name took $wall s, budget ${budget[$name]} s" | tee -a "$TIMES/over_budget.txt" >&3
  fi
}
# behind NAME COMMAND...: runs COMMAND (a stage) in the background, in a process group of its
# own that ends with the script, its output in out/test_times/NAME.log; wait_behind NAME
# waits for it (and shows the end of that log when it failed)
declare -A behind_pid=()
behind() {
  local name=$1
  shift
  set -m
  "$@" > "$TIMES/$name.log" 2>&1 &
  behind_pid[$name]=$!
  set +m
}
trap 'for p in "${behind_pid[@]}"; do kill -- "-$p" 2> /dev/null; done; true' EXIT
wait_behind() {
  local rc=0
  wait "${behind_pid[$1]}" || rc=$?
  unset "behind_pid[$1]"
  [ $rc = 0 ] && return 0
  tail -40 "$TIMES/$1.log"
  echo "test.sh: $1 failed (exit $rc; its log: out/test_times/$1.log)" >&2
  return 1
}
# run_ctest NAME BUILD [ENV=VALUE...] [-- CTEST_ARGS...]: the ctest of BUILD, its JUnit report NAME.xml
run_ctest() {
  local name=$1 dir=$2 envs=()
  shift 2
  while [ $# -gt 0 ] && [ "$1" != -- ]; do envs+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  (cd "$dir" && env "${envs[@]}" ctest --output-on-failure -j2 --output-junit "$TIMES/$name.xml" "$@")
}
# ctest -j2 on two cores: OpenMP threads that spin at a barrier take the core from the
# other test (here, four CLI tests at -j2: 62 s wall spinning, 55 s passive)
export OMP_WAIT_POLICY=passive
stage setup bash scripts/setup.sh
stage format bash scripts/check_format.sh
stage build bash scripts/build.sh build
if [ $quick = 1 ]; then
  stage ctest_quick run_ctest ctest_quick build -- -LE long
  echo "== test.sh --quick: passed in ${SECONDS} s (the full suite: scripts/test.sh)"
  exit 0
fi
sanitize=1
[ "${FS_NO_SANITIZE:-0}" = 1 ] && sanitize=0
# -O1, as the fuzz build (tests/fuzz/build.sh): measured here, its ctest takes 624 s
# against 909 s at -O0 and its build 166 s longer, and OpenVDB's templates stop
# dominating the levelset tests (test_levelset 24 s against 144 s)
asan_build() {
  bash scripts/build.sh build-asan -DFS_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_C_FLAGS_DEBUG="-O1 -g" -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g"
}
# The other builds run behind the normal ctest and the studies, at nice 19: those leave
# part of the 2 cores idle (the normal ctest -j2 alone used 1.2 cores), which the builds
# take without slowing the tests much.
builds_behind() {
  renice -n 19 -p $BASHPID > /dev/null
  stage lean_build bash scripts/build_lean.sh build-lean
  # pip install . from this clone into a fresh venv, CMake building build-pip/ (README)
  stage pip_install bash tests/pip_install.sh "$PWD" "" "$PWD/out/pip_install"
  [ $sanitize = 1 ] || return 0
  stage asan_build asan_build
  stage fuzz_build bash tests/fuzz/build.sh build-fuzz
}
behind builds builds_behind
# every study script at small sizes (outputs under out/quick/, never results/), beside the
# normal ctest: neither fills the 2 cores alone, and neither reads what the other writes
behind studies stage studies bash experiments/run_all.sh --quick
stage ctest run_ctest ctest build
wait_behind studies
cat "$TIMES/studies.log"
stage builds_wait wait_behind builds
[ -z "${behind_pid[builds]:-}" ] || wait_behind builds # (--only without builds_wait)
lean_tests() {
  run_ctest lean_ctest build-lean FLUIDSURF_GL=egl
  bash tests/lean_vs_full.sh build/fluidsurf build-lean/fluidsurf build-lean/test-out/lean_vs_full
}
stage lean_ctest lean_tests
if [ $sanitize = 1 ]; then
  # Default (fast) unwinding: the slow unwinder deadlocks inside LLVM's JIT
  # registration (libgcc's unwinder lock re-entered through malloc).
  stage asan_ctest run_ctest asan_ctest build-asan UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # seeded, every seed and regression file, then at most tests/fuzz/smoke_runs.txt's runs:
  # the start of the search checked clean (tests/fuzz/run.sh; the campaigns explore)
  stage fuzz env FS_FUZZ_SEED=1 bash tests/fuzz/run.sh 10
fi
echo "== test.sh: passed in ${SECONDS} s (budget 2400 s)"
[ -n "$only" ] || [ $SECONDS -le 2400 ] || echo "== test.sh: OVER BUDGET: the run took ${SECONDS} s, budget 2400 s" >> "$TIMES/over_budget.txt"
cat "$TIMES/over_budget.txt"
