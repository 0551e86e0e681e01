#!/usr/bin/env bash
# Every shader program fluidsurf compiles, exactly as the binary hands it to the driver
# (FS_SHADER_DUMP: includes expanded, defines inserted; common/gl/shader_dump.h), checked
# by the Khronos reference compiler as GLSL 4.50 core with OpenGL semantics
# (tests/glsl_validate.py). What compiles them: compare of every method, plain and with
# --counters (the counting variants); the GPU simulator; the viewer with a simulation
# (under Xvfb, in builds with GLFW).
# usage: tests/glsl_validate.sh SRC BIN OUT [view]
set -u
SRC=$1 BIN=$2 T=$3 VIEW=${4:-}
rm -rf "$T"; mkdir -p "$T/dump"
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
# run NAME CMD...: CMD with its shaders dumped into $T/dump/NAME
run() {
  local name=$1; shift
  mkdir -p "$T/dump/$name"
  FS_SHADER_DUMP=$T/dump/$name "$@" 2> "$T/$name.err" || fail "$name: $(tail -1 "$T/$name.err")"
}
scene=$SRC/experiments/scenes/dam_break.json
# the sprite methods on both splat paths (common/gl/gl_splat.h)
splat=(--set spheres.splat=raster,compute)
run compare "$BIN" compare "$scene" -W 32 -H 32 -q --no-cache "${splat[@]}" -o "$T/compare"
run counters "$BIN" compare "$scene" -W 32 -H 32 -q --no-cache --counters "${splat[@]}" -o "$T/counters"
run simulate "$BIN" simulate dam_break --gpu --particles 500 --frames 1 -q -o "$T/sim_%04d.ply"
if [ "$VIEW" = view ]; then
  run view bash "$SRC/tests/xvfb.sh" 320x240x24 "$BIN" view --simulate dam_break --gpu --particles 500 \
    -W 64 -H 64 --frames 2
fi
python3 "$SRC/tests/glsl_validate.py" "$SRC" "$T/dump" || fails=$((fails + 1))
[ $fails = 0 ] && echo "glsl_validate: all checks passed" || { echo "glsl_validate: $fails failed"; exit 1; }
