#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: once in a normal build, then
# once more under AddressSanitizer + UndefinedBehaviorSanitizer (suppressions
# only for Mesa/LLVM, tests/lsan.supp). Set FS_NO_SANITIZE=1 to skip the second.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
(cd build && ctest --output-on-failure -j2)
if [ "${FS_NO_SANITIZE:-0}" != 1 ]; then
  bash scripts/build.sh build-asan -DFS_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug
  # Default (fast) unwinding: the slow unwinder deadlocks inside LLVM's JIT
  # registration (libgcc's unwinder lock re-entered through malloc).
  (cd build-asan && ASAN_OPTIONS=detect_leaks=1 \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j2)
fi
