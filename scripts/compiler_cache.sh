# Sourced by the build scripts (scripts/build.sh, tests/fuzz/build.sh): sets the array
# FS_LAUNCHER to CMake's compiler-launcher options for ccache where `command -v ccache`
# finds it, empty elsewhere (a machine without ccache builds everything, as before).
# CCACHE_BASEDIR (unless set) is the checkout, so the cache's entries name paths inside it
# relative to it: a fresh clone in another folder, a worktree and the checkout's own build
# folders (normal, lean, sanitizer) then share every entry whose compile is the same.
FS_LAUNCHER=()
if command -v ccache > /dev/null; then
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
  FS_LAUNCHER=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
