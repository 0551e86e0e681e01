#!/usr/bin/env bash
# Sets up, builds and installs fluidsurf into PREFIX (default ~/.local): the
# command, libfluidsurf.so with its header, pkg-config and CMake files, and the
# Python module. Prints the variables a shell needs to use them.
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=$(realpath -m "${1:-$HOME/.local}")
bash scripts/setup.sh
bash scripts/build.sh build
cmake --install build --prefix "$prefix" > /dev/null
site=$(sed -n 's/^FS_PYTHON_SITE:STRING=//p' build/CMakeCache.txt)
libdir=$(sed -n 's/^CMAKE_INSTALL_LIBDIR:PATH=//p' build/CMakeCache.txt)
echo "install: fluidsurf in $prefix; to use it:"
echo "  export PATH=\"$prefix/bin:\$PATH\" LD_LIBRARY_PATH=\"$prefix/$libdir\" PKG_CONFIG_PATH=\"$prefix/$libdir/pkgconfig\""
echo "  export PYTHONPATH=\"$prefix/$site\"   # then: /usr/bin/python3 -c 'import fluidsurf'"
