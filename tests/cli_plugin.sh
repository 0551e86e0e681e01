#!/usr/bin/env bash
# OpenImageIO is a module loaded on the first EXR or image-read call
# (common/report/oiio_plugin.h): commands that write no EXR run without it (PNGs are
# written by png_write.c); one that needs it and cannot load it
# exits 1 with one line naming the module and leaves no file; an installed tree
# loads its own copy of the module.
#   cli_plugin.sh BIN SRC BUILD T
set -u
BIN=$1 SRC=$2 BUILD=$3 T=$4
rm -rf "$T"; mkdir -p "$T/nomodule"
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
ply=$SRC/experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply

# without the module: info, mesh and a PNG render work (they never load it) ...
FLUIDSURF_PLUGIN_DIR=$T/nomodule "$BIN" info "$ply" > "$T/info.txt" 2> "$T/err" || fail "info without the module: $(cat "$T/err")"
FLUIDSURF_PLUGIN_DIR=$T/nomodule "$BIN" mesh "$ply" -q --set mesh.cube=2 -o "$T/m.ply" 2> "$T/err" && [ -s "$T/m.ply" ] ||
  fail "mesh without the module: $(cat "$T/err")"
FLUIDSURF_PLUGIN_DIR=$T/nomodule "$BIN" render "$ply" -W 32 -H 32 --method spheres -q -o "$T/p.png" 2> "$T/err" &&
  [ -s "$T/p.png" ] || fail "PNG render without the module: $(cat "$T/err")"
# ... and an EXR cannot be written: exit 1, one line naming the module, no file
FLUIDSURF_PLUGIN_DIR=$T/nomodule "$BIN" render "$ply" -W 32 -H 32 --method spheres -q -o "$T/x.exr" 2> "$T/err"
rc=$?
if [ $rc -ne 1 ] || [ "$(wc -l < "$T/err")" -ne 1 ] || ! grep -q "^fluidsurf: .*fluidsurf-oiio.so" "$T/err"; then
  fail "EXR render without the module: exit $rc, $(cat "$T/err")"
fi
ls "$T"/x.exr "$T"/.x.exr* > /dev/null 2>&1 && fail "render without the module left a file"
echo "without the module: $(cat "$T/err")"

# an installed tree loads the module beside it, not the build tree's
cmake --install "$BUILD" --prefix "$T/prefix" > "$T/install.log" 2>&1 || fail "cmake --install: $(tail -2 "$T/install.log")"
LD_DEBUG=files "$T/prefix/bin/fluidsurf" render "$ply" -W 32 -H 32 --method spheres -q -o "$T/y.exr" 2> "$T/ld.txt" ||
  fail "installed render: $(grep -v '^ *[0-9]*:' "$T/ld.txt")"
loaded=$(grep -o "file=[^ ]*fluidsurf-oiio.so" "$T/ld.txt" | head -1 | sed 's/^file=//')
case $loaded in
  "$T/prefix/"*) echo "installed: loaded $loaded" ;;
  *) fail "installed binary loaded the module from '${loaded:-nowhere}'" ;;
esac
[ -s "$T/y.exr" ] || fail "installed render wrote no image"

[ $fails -eq 0 ] && echo "cli_plugin: all passed" || { echo "cli_plugin: $fails failed"; exit 1; }
