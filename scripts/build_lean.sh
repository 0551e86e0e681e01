#!/usr/bin/env bash
# Builds the lean fluidsurf into build-lean/ (or $1): every optional library off
# (FS_WITH_VTK, FS_WITH_OPENVDB, FS_WITH_OIIO, FS_WITH_GLFW, FS_WITH_OSMESA), EGL
# as the default context, the experiment tools too. RelWithDebInfo like
# scripts/build.sh (which it calls), so outputs match the full build's where the code is shared.
# The binaries carry the rpath $ORIGIN: a folder packed by scripts/pack_lean.sh finds
# its libraries (and libEGL.so.1, dlopen'ed) beside them. DT_RPATH, not DT_RUNPATH:
# only the executable's DT_RPATH also serves the dependencies of libEGL.so.1 (glvnd's
# libGLdispatch.so.0, which carries no path of its own). Then scripts/check_lean.sh
# checks what the binary links.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-lean}
shift || true
bash scripts/build.sh "$dir" \
  -DFS_WITH_VTK=OFF -DFS_WITH_OPENVDB=OFF -DFS_WITH_OIIO=OFF -DFS_WITH_GLFW=OFF -DFS_WITH_OSMESA=OFF \
  '-DCMAKE_BUILD_RPATH=$ORIGIN' -DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags "$@"
bash scripts/check_lean.sh "$dir/fluidsurf"
