#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: once in a normal build; then the
# lean build (scripts/build_lean.sh: no VTK, OpenVDB, OpenImageIO, GLFW, OSMesa)
# with its own tests on EGL, and every method rendered by both builds compared
# (tests/lean_vs_full.sh); then once more under AddressSanitizer +
# UndefinedBehaviorSanitizer (suppressions only for Mesa/LLVM and two libraries'
# error paths, tests/lsan.supp), which also replays the fuzz seeds and regression
# files (tests/fuzz); and last every libFuzzer target of tests/fuzz for 30 s
# (clang, ASan + UBSan: tests/fuzz/run.sh). Set FS_NO_SANITIZE=1 to skip the last two.
# After the normal build's tests, experiments/run_all.sh --quick runs every study script
# at small sizes. First of all, the C style check (scripts/check_format.sh, .clang-format).
set -euo pipefail
cd "$(dirname "$0")/.."
# each stage's end, in seconds since the start, and the disk this checkout takes and the
# disk left: where CI's time and disk go (a CI run once ran out of disk)
stage() {
  echo "== test.sh: $1 done at ${SECONDS} s; $(du -sm . | cut -f1) MB here, $(df -Pm . | awk 'NR == 2 {print $4}') MB free"
}
# ctest -j2 on two cores: OpenMP threads that spin at a barrier take the core from the
# other test (here, four CLI tests at -j2: 62 s wall spinning, 55 s passive)
export OMP_WAIT_POLICY=passive
bash scripts/setup.sh
stage setup
bash scripts/check_format.sh
bash scripts/build.sh build
stage build
(cd build && ctest --output-on-failure -j2)
stage ctest
# every study script at small sizes (outputs under out/quick/, never results/)
bash experiments/run_all.sh --quick
stage 'run_all --quick'
bash scripts/build_lean.sh build-lean
(cd build-lean && FLUIDSURF_GL=egl ctest --output-on-failure -j2)
bash tests/lean_vs_full.sh build/fluidsurf build-lean/fluidsurf build-lean/test-out/lean_vs_full
stage lean
if [ "${FS_NO_SANITIZE:-0}" != 1 ]; then
  # -O1, as the fuzz build (tests/fuzz/build.sh): measured here, its ctest takes 624 s
  # against 909 s at -O0 and its build 166 s longer, and OpenVDB's templates stop
  # dominating the levelset tests (test_levelset 24 s against 144 s)
  bash scripts/build.sh build-asan -DFS_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_C_FLAGS_DEBUG="-O1 -g" -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g"
  stage 'sanitizer build'
  # Default (fast) unwinding: the slow unwinder deadlocks inside LLVM's JIT
  # registration (libgcc's unwinder lock re-entered through malloc).
  (cd build-asan && \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j2)
  stage 'sanitizer ctest'
  # seeded, at most tests/fuzz/smoke_runs.txt's runs: the search checked clean (tests/fuzz/run.sh)
  FS_FUZZ_SEED=1 bash tests/fuzz/run.sh 30
  stage fuzz
fi
