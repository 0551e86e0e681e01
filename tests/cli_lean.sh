#!/usr/bin/env bash
# The lean build (scripts/build_lean.sh) end to end, through its default EGL context:
# every method renders the BGEO dam break to EXR and PNG, compare and diff run,
# PLY/BGEO/CSV particle files are read; and each left-out library (OFF names
# them: VTK OPENVDB OIIO GLFW OSMESA) is refused with exit 2, one line
# "fluidsurf: ... needs a build with FS_WITH_X=ON" and no output file.
set -u
BIN=$1 SRC=$2 T=$3 OFF=$4
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
off() { case " $OFF " in *" $1 "*) return 0 ;; esac; return 1; }
data=$SRC/experiments/data/splashsurf
bgeo=$data/dam_break_frame_9_6859_particles.bgeo
printf '{"particles": "%s", "radius": 0.025, "volume_scale": 0.8, "camera": {"eye": [3.2, 3.4, 5.4], "target": [0.0, 1.0, 0.0], "fov": 40, "width": 64, "height": 64}}' \
  "$bgeo" > "$T/dam.json"

# refused ARGS... (the last -o/--export path given as $OUTFILE): exit 2, one line naming the option, no file
refused() {
  local opt=$1 what=$2; shift 2
  env ${ENVSET:-} "$BIN" "$@" > /dev/null 2> "$T/err"; local rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "^fluidsurf: .*needs a build with FS_WITH_$opt=ON" "$T/err" && { [ -z "${OUTFILE:-}" ] || [ ! -e "$OUTFILE" ]; }' \
    "$what refused (rc $rc: $(head -c 200 "$T/err"))"
}

# 1. every method on the default (EGL) context: EXR with the G-buffer, PNG, identical to itself under diff
methods=$("$BIN" methods | grep -v '^ ' | awk '{print $1}')
check '[ "$(echo $methods | wc -w)" -ge 6 ]' "methods lists $(echo $methods | tr '\n' ' ')"
for m in $methods; do
  "$BIN" render "$T/dam.json" --method "$m" -q --timings -o "$T/$m.exr" > "$T/$m.timings" 2> "$T/err"; rc=$?
  check '[ $rc -eq 0 ] && [ -s "$T/$m.exr" ]' "render $m to EXR ($(head -c 200 "$T/err"))"
  [ "$m" = reference ] || check 'tail -n +2 "$T/$m.timings" | grep -v ",CPU$" | grep -q "llvmpipe\|NVIDIA\|Mesa"' "$m ran on the GL context"
  "$BIN" diff "$T/$m.exr" "$T/$m.exr" --fail-iou 1 --fail-normal-deg 0 --fail-depth-r 0 > "$T/$m.diff" 2>&1; rc=$?
  check '[ $rc -eq 0 ] && grep -qx "mask_iou 1" "$T/$m.diff"' "diff $m against itself: IoU 1"
done
"$BIN" render "$T/dam.json" --method spheres -q -o "$T/spheres.png"; rc=$?
check '[ $rc -eq 0 ] && [ "$(head -c 4 "$T/spheres.png" | od -An -c | tr -d " ")" = "211PNG" ]' "render to PNG"
# A PNG write cut short (the file size limit stands in for a full disk): an error, nothing left.
( trap '' XFSZ; ulimit -f 1; "$BIN" render "$T/dam.json" --method spheres -q -W 256 -H 256 -o "$T/short.png" ) 2> "$T/short.err"; rc=$?
check '[ $rc -eq 1 ] && [ ! -e "$T/short.png" ] && [ -z "$(ls -A "$T" | grep "^\.short\.png\.tmp")" ] && grep -q "short.png: cannot write: " "$T/short.err"' \
  "a short PNG write fails and leaves no file (rc $rc: $(head -c 200 "$T/short.err"))"
"$BIN" diff "$T" "$T" > /dev/null 2> "$T/folder.err"; rc=$?
check '[ $rc -eq 2 ] && grep -q ": is a folder$" "$T/folder.err"' "diff of a folder: bad input, 'is a folder' ($(head -c 200 "$T/folder.err"))"
"$BIN" diff "$T/spheres.exr" "$T/reference.exr" --fail-iou 0.999 > "$T/sr.diff" 2>&1; rc=$?
check '[ $rc -eq 3 ]' "diff spheres vs reference exits 3 past --fail-iou"

# 2. compare: every file, panel with its labels
"$BIN" compare "$T/dam.json" --methods spheres,aniso_ssf,reference --reference reference -W 48 -H 48 --repeat 1 -q --no-cache -o "$T/cmp" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && [ ! -s "$T/err" ]' "compare runs ($(head -c 200 "$T/err"))"
for f in spheres.exr spheres.png aniso_ssf.exr reference.exr diff_spheres.png metrics.csv timings.csv panel.png report.md; do
  check '[ -s "$T/cmp/$f" ]' "compare writes $f"
done
check '[ "$(awk -F, "!/^#/ && \$1==\"reference\" {print \$5}" "$T/cmp/metrics.csv")" = 1 ]' "compare: reference against itself IoU 1"
# Without its font file the lean compare still writes everything, and says so once.
FLUIDSURF_FONT=$T/no-such-font.ttf "$BIN" compare "$T/dam.json" --methods spheres -W 32 -H 32 --repeat 1 --no-cache -o "$T/nofont" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/nofont/panel.png" ] && [ -s "$T/nofont/diff_spheres.png" ] && [ "$(grep -c "^fluidsurf: note: .*font not found" "$T/err")" -eq 1 ]' \
  "compare without the font: all files, one note ($(grep font "$T/err" | head -c 200))"

# 3. the particle formats the lean build reads
"$BIN" convert "$bgeo" -o "$T/dam.ply" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && "$BIN" info "$T/dam.ply" | grep -q "^particles: *6859"' "BGEO -> PLY, info reads it"
printf 'x,y,z\n0,0,0\n0.05,0,0\n0,0.05,0\n' > "$T/three.csv"
check '"$BIN" info "$T/three.csv" --radius 0.025 | grep -q "^particles: *3"' "CSV read"

# legacy .vtk is fluidsurf's own code in every build: read, written, read back
"$BIN" convert "$data/cube_2366_particles.vtk" -o "$T/cube.vtk" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && "$BIN" info "$T/cube.vtk" | grep -q "^particles: *2366"' "legacy VTK read, written and read back"

# 4. refusals of what the lean build leaves out
if off VTK; then
  OUTFILE= refused VTK "VTU input" info "$data/fluid_250_particles.vtu"
fi
if off OPENVDB; then
  OUTFILE=$T/out.vdb refused OPENVDB "VDB points output" convert "$bgeo" -o "$T/out.vdb"
  OUTFILE=$T/sim.csv refused OPENVDB "simulate to .vdb" simulate dam_break --frames 1 --particles 500 -q -o "$T/sim_%04d.vdb" --stats "$T/sim.csv"
  printf 'not a vdb' > "$T/in.vdb"
  OUTFILE= refused OPENVDB "VDB points input" info "$T/in.vdb"
  OUTFILE=$T/grid.vdb refused OPENVDB "VDB density grid export" render "$T/dam.json" --method surfels -q --export "$T/grid.vdb"
  OUTFILE=$T/ls.exr refused OPENVDB "the levelset method" render "$T/dam.json" --method levelset -q -o "$T/ls.exr"
  OUTFILE=$T/lscmp/report.md refused OPENVDB "the levelset method in compare" compare "$T/dam.json" --methods levelset -q -o "$T/lscmp"
  check '! "$BIN" methods | grep -q "^levelset"' "levelset is not registered"
  OUTFILE=$T/me.exr refused OPENVDB "the mesh method" render "$T/dam.json" --method mesh -q -o "$T/me.exr"
  OUTFILE=$T/me.ply refused OPENVDB "fluidsurf mesh" mesh "$T/dam.ply" -q -o "$T/me.ply"
  check '! "$BIN" methods | grep -q "^mesh"' "mesh is not registered"
fi
if off OIIO; then
  # PNG and EXR are read by every build's own code; OpenImageIO reads tiled or deep EXRs
  OUTFILE= refused OIIO "a tiled EXR" diff "$SRC/tests/fuzz/corpus_exr_core/tiled.exr" "$SRC/tests/fuzz/corpus_exr_core/tiny.exr"
fi
if off GLFW; then
  OUTFILE= refused GLFW "view" view "$T/dam.json"
fi
if off OSMESA; then
  OUTFILE=$T/os.exr refused OSMESA "--gl osmesa" render "$T/dam.json" --method spheres --gl osmesa -o "$T/os.exr"
  OUTFILE=$T/os.exr ENVSET=FLUIDSURF_GL=osmesa refused OSMESA "FLUIDSURF_GL=osmesa" render "$T/dam.json" --method spheres -o "$T/os.exr"
fi
check '[ -z "$(find "$T" -name ".*.tmp*")" ]' "no temporary files left"

[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
