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
# at small sizes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
(cd build && ctest --output-on-failure -j2)
# every study script at small sizes (outputs under out/quick/, never results/)
bash experiments/run_all.sh --quick
bash scripts/build_lean.sh build-lean
(cd build-lean && FLUIDSURF_GL=egl ctest --output-on-failure -j2)
bash tests/lean_vs_full.sh build/fluidsurf build-lean/fluidsurf build-lean/test-out/lean_vs_full
if [ "${FS_NO_SANITIZE:-0}" != 1 ]; then
  bash scripts/build.sh build-asan -DFS_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug
  # Default (fast) unwinding: the slow unwinder deadlocks inside LLVM's JIT
  # registration (libgcc's unwinder lock re-entered through malloc).
  (cd build-asan && \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j2)
  # seeded, at most tests/fuzz/smoke_runs.txt's runs: the search checked clean (tests/fuzz/run.sh)
  FS_FUZZ_SEED=1 bash tests/fuzz/run.sh 30
fi
