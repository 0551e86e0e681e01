#!/usr/bin/env bash
# scripts/pack_lean.sh --gl packs a lean build (BUILD) into OUT; the packed fluidsurf
# runs with an empty LD_LIBRARY_PATH, ldd resolves every carried library from OUT,
# and it renders through EGL with the carried GL loaders.
set -u
SRC=$1 BUILD=$2 T=$3
rm -rf "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
bash "$SRC/scripts/pack_lean.sh" --gl --build "$BUILD" "$T/pack" > "$T.log" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "^pack_lean: .* bytes$" "$T.log"' "pack_lean.sh runs and prints the size ($(tail -1 "$T.log"))"
# OpenEXRCore's SONAME (libOpenEXRCore-3_1.so.30 on Debian 12) as the build links it.
exrcore=$(ldd "$BUILD/fluidsurf" | awk '$1 ~ /^libOpenEXRCore/ {print $1; exit}')
check '[ -n "$exrcore" ]' "the lean fluidsurf links OpenEXRCore (${exrcore:-none in ldd})"
for f in fluidsurf density_bench inacio_tables render_bench libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 $exrcore libgomp.so.1; do
  check '[ -f "$T/pack/$f" ] && [ ! -L "$T/pack/$f" ]' "packs $f as a real file"
done
env -i PATH=/usr/bin:/bin LD_LIBRARY_PATH= "$T/pack/fluidsurf" methods > "$T/methods.txt" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "^spheres" "$T/methods.txt"' "packed fluidsurf methods runs with an empty LD_LIBRARY_PATH"
ldd "$T/pack/fluidsurf" > "$T/ldd.txt"
carried=$(ls "$T/pack" | grep '\.so')
for lib in $carried; do
  case $lib in libEGL*|libGLdispatch*|libOpenGL*) continue ;; esac
  check 'grep -q "^[[:space:]]*$lib => $T/pack/$lib " "$T/ldd.txt"' "ldd resolves $lib from the pack"
done
env -i PATH=/usr/bin:/bin LD_LIBRARY_PATH= LD_DEBUG=libs "$T/pack/fluidsurf" render "$SRC/experiments/scenes/box.json" \
  --method spheres -W 32 -H 32 -q -o "$T/box.exr" > /dev/null 2> "$T/debug.txt"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/box.exr" ]' "packed fluidsurf renders through EGL"
check 'grep -q "calling init: $T/pack/libEGL.so.1" "$T/debug.txt" && grep -q "calling init: $T/pack/libGLdispatch.so.0" "$T/debug.txt"' \
  "it loads the carried libEGL.so.1 and libGLdispatch.so.0"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
