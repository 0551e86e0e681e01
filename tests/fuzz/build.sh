#!/usr/bin/env bash
# Builds every libFuzzer target of tests/fuzz into BUILD (default build-fuzz: clang -O1,
# -DFS_FUZZ=ON, ASan + UBSan on every file), configuring it the first time; the log is
# BUILD/fuzz_build.log. Used by run.sh and campaign.sh.
#   tests/fuzz/build.sh [BUILD]
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build-fuzz}
source scripts/compiler_cache.sh # FS_LAUNCHER, CCACHE_BASEDIR
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  # -O1, as libFuzzer's documentation advises: OpenVDB's headers under the sanitizers
  # take minutes a file at -O2
  cmake -S . -B "$BUILD" -DFS_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-O1 -g" -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
    "${FS_LAUNCHER[@]}" > /dev/null || exit 1
fi
cmake --build "$BUILD" --target fuzz_all -j"$(nproc)" > "$BUILD/fuzz_build.log" 2>&1 ||
  { tail -20 "$BUILD/fuzz_build.log"; echo "fuzz: the build failed ($BUILD/fuzz_build.log)" >&2; exit 1; }
