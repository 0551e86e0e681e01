#!/usr/bin/env bash
# `pip install .` as README says (pyproject.toml, setup.py): into a fresh virtual
# environment made with --system-site-packages (Debian's NumPy and cffi), with
# --no-build-isolation and no package index; then that environment's python imports
# the installed package (not this tree's python/), its own libfluidsurf, and renders.
# BUILD: an existing build to pack as it is (FLUIDSURF_BUILD_DIR: the ctest), or ""
# for the whole path, CMake configuring and building build-pip/ in SRC (scripts/test.sh).
# Usage: pip_install.sh SRC BUILD OUTDIR
set -u
SRC=$1 BUILD=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
ls -A "$SRC" > "$T/tree.before"
/usr/bin/python3 -m venv --system-site-packages "$T/venv" > "$T/venv.log" 2>&1; rc=$?
check '[ $rc -eq 0 ] && [ -x "$T/venv/bin/pip" ]' "a fresh venv with pip: $(tail -c 300 "$T/venv.log")"
if [ -n "$BUILD" ]; then export FLUIDSURF_BUILD_DIR=$BUILD; else unset FLUIDSURF_BUILD_DIR; fi
start=$SECONDS
(cd "$T" && env -u PYTHONPATH "$T/venv/bin/pip" install --no-build-isolation --no-index "$SRC") > "$T/pip.log" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "Successfully installed fluidsurf-" "$T/pip.log"' \
  "pip install --no-build-isolation . ($((SECONDS - start)) s): $(tail -c 600 "$T/pip.log")"
ls -A "$SRC" > "$T/tree.after"
[ -n "$BUILD" ] && check 'cmp -s "$T/tree.before" "$T/tree.after"' "the source tree's top level is as it was: $(diff "$T/tree.before" "$T/tree.after" | tr '\n' ' ')"
# the venv's python, from elsewhere, with nothing on PYTHONPATH: the installed package
cat > "$T/use.py" << 'PY'
import sys

import numpy as np

import fluidsurf

assert fluidsurf.__file__.startswith(sys.prefix), fluidsurf.__file__
maps = open("/proc/self/maps").read()
lib = [line.split()[-1] for line in maps.splitlines() if "libfluidsurf.so" in line]
assert lib and all(p.startswith(sys.prefix) for p in lib), lib
rng = np.random.default_rng(1)
pos = (rng.random((400, 3)) * 0.3).astype(np.float32)
out = fluidsurf.render(pos, 0.025, method="raycast_pca", width=48, height=32)
assert out["depth"].shape == (32, 48) and out["coverage"].sum() > 100, out["coverage"].sum()
print("rendered", int(out["coverage"].sum()), "px with", fluidsurf.version(), "from", lib[0])
PY
(cd "$T" && env -u PYTHONPATH -u FLUIDSURF_LIBRARY "$T/venv/bin/python" use.py) > "$T/use.out" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "^rendered" "$T/use.out"' "the venv imports the package and renders: $(tail -c 600 "$T/use.out")"
"$T/venv/bin/pip" show fluidsurf > "$T/show.out" 2>&1
check 'grep -q "^Version: $(sed -n "s/^project(fluidsurf VERSION \([0-9.]*\).*/\1/p" "$SRC/CMakeLists.txt")$" "$T/show.out"' \
  "pip knows it, at the project's version: $(grep Version "$T/show.out")"
echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
