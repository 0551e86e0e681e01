#!/usr/bin/env bash
# OpenImageIO is a module loaded only to draw text and to read EXRs that
# OpenEXRCore's scanline reader does not (tiled, deep): PNGs and EXRs are written
# and read without it (png_write.c, image_stb.c, image_exr_core.c). So renders to
# PNG and EXR and `diff` of two EXRs neither need it nor load it (nor
# libOpenImageIO); a command that needs it and cannot load it exits 1 with one
# line naming the module and leaves no file; with it, a tiled EXR reads as its
# scanline original; an installed tree loads its own copy of the module.
#   cli_plugin.sh BIN SRC BUILD T
set -u
BIN=$1 SRC=$2 BUILD=$3 T=$4
rm -rf "$T"; mkdir -p "$T/nomodule"
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
ply=$SRC/experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply
nomod() { FLUIDSURF_PLUGIN_DIR=$T/nomodule "$@"; }

# without the module: info, mesh, PNG and EXR renders and diff of EXRs work ...
nomod "$BIN" info "$ply" > "$T/info.txt" 2> "$T/err" || fail "info without the module: $(cat "$T/err")"
nomod "$BIN" mesh "$ply" -q --set mesh.cube=2 -o "$T/m.ply" 2> "$T/err" && [ -s "$T/m.ply" ] ||
  fail "mesh without the module: $(cat "$T/err")"
for f in p.png x.exr; do
  nomod "$BIN" render "$ply" -W 32 -H 32 --method spheres -q -o "$T/$f" 2> "$T/err" && [ -s "$T/$f" ] ||
    fail "$f render without the module: $(cat "$T/err")"
done
nomod "$BIN" render "$ply" -W 32 -H 32 --method reference -q -o "$T/ref.exr" 2> "$T/err" ||
  fail "reference EXR render without the module: $(cat "$T/err")"
nomod "$BIN" diff "$T/x.exr" "$T/ref.exr" > "$T/diff.txt" 2> "$T/err" && grep -q '^mask_iou ' "$T/diff.txt" ||
  fail "diff of EXRs without the module: $(cat "$T/err")"
# ... and load neither the module nor OpenImageIO (the loader's own record)
for f in p.png y.exr; do
  LD_DEBUG=files "$BIN" render "$ply" -W 32 -H 32 --method spheres -q -o "$T/$f" 2> "$T/ld_$f.txt" ||
    fail "$f render: $(grep -v '^ *[0-9]*:' "$T/ld_$f.txt")"
  if grep -q "file=[^ ]*\(fluidsurf-oiio\|libOpenImageIO\)" "$T/ld_$f.txt"; then
    fail "a render to $f loaded $(grep -o "file=[^ ]*\(fluidsurf-oiio\|libOpenImageIO\)[^ ]*" "$T/ld_$f.txt" | head -1)"
  else
    echo "a render to $f loads neither the module nor libOpenImageIO"
  fi
done

# Text needs the module: diff's heatmap panel cannot be drawn without it (exit 1, one
# line naming the module, no file) and is with it.
nomod "$BIN" diff "$T/x.exr" "$T/ref.exr" -o "$T/panel.png" > /dev/null 2> "$T/err"
rc=$?
if [ $rc -ne 1 ] || [ "$(wc -l < "$T/err")" -ne 1 ] || ! grep -q "^fluidsurf: .*fluidsurf-oiio.so" "$T/err"; then
  fail "text without the module: exit $rc, $(cat "$T/err")"
fi
ls "$T"/panel.png "$T"/.panel.png* > /dev/null 2>&1 && fail "a panel without the module left a file"
echo "text without the module: $(cat "$T/err")"
LD_DEBUG=files "$BIN" diff "$T/x.exr" "$T/ref.exr" -o "$T/panel.png" > /dev/null 2> "$T/ld_panel.txt" && [ -s "$T/panel.png" ] ||
  fail "panel with the module: $(grep -v '^ *[0-9]*:' "$T/ld_panel.txt")"
grep -q "file=[^ ]*fluidsurf-oiio.so" "$T/ld_panel.txt" || fail "the panel's text did not go through the module"

# A tiled EXR is read through the module: the same G-buffer as its scanline original.
if oiiotool "$T/ref.exr" --tile 16 16 -o "$T/tiled.exr" 2> "$T/err"; then
  nomod "$BIN" diff "$T/tiled.exr" "$T/ref.exr" > /dev/null 2> "$T/err"
  rc=$?
  [ $rc -eq 1 ] && grep -q "fluidsurf-oiio.so" "$T/err" || fail "tiled EXR without the module: exit $rc, $(cat "$T/err")"
  "$BIN" diff "$T/tiled.exr" "$T/ref.exr" --fail-iou 1 --fail-depth-r 0 --fail-normal-deg 0 > "$T/tiled.txt" 2> "$T/err" &&
    grep -q '^mask_iou 1$' "$T/tiled.txt" || fail "tiled EXR with the module: $(cat "$T/err")"
else
  fail "oiiotool cannot write a tiled EXR (openimageio-tools): $(cat "$T/err")"
fi

# an installed tree loads the module beside it, not the build tree's
cmake --install "$BUILD" --prefix "$T/prefix" > "$T/install.log" 2>&1 || fail "cmake --install: $(tail -2 "$T/install.log")"
LD_DEBUG=files "$T/prefix/bin/fluidsurf" diff "$T/x.exr" "$T/ref.exr" -o "$T/panel2.png" > /dev/null 2> "$T/ld.txt" ||
  fail "installed diff -o: $(grep -v '^ *[0-9]*:' "$T/ld.txt")"
loaded=$(grep -o "file=[^ ]*fluidsurf-oiio.so" "$T/ld.txt" | head -1 | sed 's/^file=//')
case $loaded in
  "$T/prefix/"*) echo "installed: loaded $loaded" ;;
  *) fail "installed binary loaded the module from '${loaded:-nowhere}'" ;;
esac
[ -s "$T/panel2.png" ] || fail "installed diff wrote no panel"

[ $fails -eq 0 ] && echo "cli_plugin: all passed" || { echo "cli_plugin: $fails failed"; exit 1; }
