#!/usr/bin/env bash
# Sets up, builds and installs fluidsurf into PREFIX (default ~/.local): the command,
# libfluidsurf.so with its header, pkg-config and CMake files, its OpenImageIO plugin, and
# the Python module. Prints the variables a shell needs to use them.
#
#   scripts/install.sh [PREFIX] [--build DIR] [--install-only] [--dry-run]
#
# It builds only what it installs (the targets fluidsurf and fluidsurf_lib; no tests, fuzz
# replays or experiment tools), in a build folder of its own: DIR, default build-install/,
# configured with -DFS_TESTS=OFF when new (an existing DIR keeps its options; the checkout's
# build/ and its tests are never touched unless DIR names it). --install-only installs DIR
# as it is built (no apt, no configure, no build): DIR must hold both targets. --dry-run
# prints the plan and runs nothing. The Python module is for Debian's /usr/bin/python3, whose
# python3-numpy and python3-cffi scripts/setup.sh installs (pip install . puts it into a
# virtual environment instead: README, "As a library").
set -euo pipefail
cd "$(dirname "$0")/.."
die() { echo "install.sh: $*" >&2; exit 2; }
prefix="" dir=build-install dry=0 only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) [ $# -ge 2 ] && [ -n "$2" ] && [ "${2#-}" = "$2" ] || die "--build needs a folder"; dir=$2; shift 2 ;;
    --dry-run) dry=1; shift ;;
    --install-only) only=1; shift ;;
    -h|--help) sed -n '2,15s/^# \{0,1\}//p' "$0"; exit 0 ;;
    -*) die "unknown option $1 (usage: scripts/install.sh [PREFIX] [--build DIR] [--install-only] [--dry-run])" ;;
    *) [ -z "$prefix" ] || die "two prefixes ($prefix and $1)"; prefix=$1; shift ;;
  esac
done
prefix=$(realpath -m "${prefix:-$HOME/.local}")
configure=(cmake -S . -B "$dir")
[ -f "$dir/CMakeCache.txt" ] || configure+=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DFS_TESTS=OFF)
build=(cmake --build "$dir" -j"$(nproc)" --target fluidsurf fluidsurf_lib)
install=(cmake --install "$dir" --prefix "$prefix")
if [ $only -eq 1 ]; then # an existing build, as it is: both installed targets must be there
  [ -f "$dir/CMakeCache.txt" ] || die "--install-only: $dir is not a build folder (no CMakeCache.txt)"
  for t in fluidsurf libfluidsurf.so.0; do
    [ -e "$dir/$t" ] || die "--install-only: $dir has no $t: build it first (cmake --build $dir --target fluidsurf fluidsurf_lib)"
  done
fi
if [ $dry -eq 1 ]; then
  [ $only -eq 1 ] || printf '%s\n' "bash scripts/setup.sh" "${configure[*]}" "${build[*]}"
  printf '%s\n' "${install[*]}"
  exit 0
fi
if [ $only -eq 0 ]; then
  bash scripts/setup.sh
  "${configure[@]}" > /dev/null
  "${build[@]}"
fi
"${install[@]}" > /dev/null
site=$(sed -n 's/^FS_PYTHON_SITE:STRING=//p' "$dir/CMakeCache.txt")
libdir=$(sed -n 's/^CMAKE_INSTALL_LIBDIR:PATH=//p' "$dir/CMakeCache.txt")
echo "install: fluidsurf in $prefix (built in $dir/); to use it:"
echo "  export PATH=\"$prefix/bin:\$PATH\" LD_LIBRARY_PATH=\"$prefix/$libdir\" PKG_CONFIG_PATH=\"$prefix/$libdir/pkgconfig\""
echo "  export PYTHONPATH=\"$prefix/$site\"   # then: /usr/bin/python3 -c 'import fluidsurf' (Debian's Python: its numpy and cffi)"
