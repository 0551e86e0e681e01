#!/usr/bin/env bash
# Configures and builds fluidsurf into build/ (or $1), Release with debug info; further
# arguments go to cmake's configure step. Through ccache where it is installed
# (scripts/compiler_cache.sh). FS_BUILD_TARGET=NAME builds only that target and what it
# links: scripts/demo.sh builds just `fluidsurf`, not the tests and tools.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}
shift || true
source scripts/compiler_cache.sh # FS_LAUNCHER
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${FS_LAUNCHER[@]}" "$@" >/dev/null
cmake --build "$dir" -j"$(nproc)" ${FS_BUILD_TARGET:+--target "$FS_BUILD_TARGET"}
