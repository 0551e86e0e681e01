#!/usr/bin/env bash
# The context on a machine that is not ours (docs/DESIGN.md, "Contexts"), through
# real EGL on Mesa's llvmpipe device: an EGL context names its renderer once on
# stderr (a note: -q silences it, OSMesa never prints it); --require-gpu and
# FLUIDSURF_REQUIRE_GPU=1 refuse a software renderer with exit 1, one line naming
# it, and nothing written; a run that makes no GL context is not refused.
# Usage: cli_require_gpu.sh BIN SRC T WITH_OSMESA WITH_GLFW RENDER_BENCH
set -u
BIN=$1 SRC=$2 T=$3 WITH_OSMESA=$4 WITH_GLFW=$5 RB=$6
unset FLUIDSURF_REQUIRE_GPU
rm -rf "$T"; mkdir -p "$T"
fails=0 skipped=
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
scene=$SRC/experiments/scenes/box.json
small="-W 32 -H 32"
# the renderer line, and the refusal's line for WHO (--require-gpu or FLUIDSURF_REQUIRE_GPU=1)
said='^fluidsurf: note: OpenGL: .+ \(EGL device [0-9]+ of [0-9]+\)$'
refusal() { echo "^fluidsurf: $1: the OpenGL renderer is (llvmpipe|softpipe).*, a software rasterizer$"; }
lines() { grep -c . "$1"; }
# refused FILE WHO OUT: exit 1 ($rc), FILE holds the one refusal line, OUT does not exist, no temporaries
refused() { [ $rc -eq 1 ] && [ "$(lines "$1")" -eq 1 ] && grep -Eq "$(refusal "$2")" "$1" && [ ! -e "$3" ] &&
            [ -z "$(ls -A "$T" | grep '\.tmp')" ]; }

# 1. EGL names its renderer once; the default kind from FLUIDSURF_GL too; -q silences it
"$BIN" render "$scene" --method spheres $small --gl egl -o "$T/egl.png" 2> "$T/egl.err"; rc=$?
check '[ $rc -eq 0 ] && [ "$(lines "$T/egl.err")" -eq 1 ] && grep -Eq "$said" "$T/egl.err"' \
  "render --gl egl: one renderer line ($(head -c 200 "$T/egl.err"))"
FLUIDSURF_GL=egl "$BIN" render "$scene" --method spheres $small -o "$T/env.png" 2> "$T/env.err"; rc=$?
check '[ $rc -eq 0 ] && grep -Eq "$said" "$T/env.err"' "FLUIDSURF_GL=egl: the renderer line ($(head -c 200 "$T/env.err"))"
"$BIN" render "$scene" --method spheres $small --gl egl -q -o "$T/q.png" 2> "$T/q.err"; rc=$?
check '[ $rc -eq 0 ] && [ ! -s "$T/q.err" ] && [ -s "$T/q.png" ]' "render --gl egl -q: nothing on stderr ($(head -c 200 "$T/q.err"))"
"$BIN" compare "$scene" --methods spheres,aniso_ssf $small --repeat 1 --no-cache --gl egl -o "$T/cmp" 2> "$T/cmp.err"; rc=$?
check '[ $rc -eq 0 ] && [ "$(grep -Ec "$said" "$T/cmp.err")" -eq 1 ] && [ "$(grep -c "OpenGL:" "$T/cmp.err")" -eq 1 ]' \
  "compare --gl egl, two GL methods: the renderer line once ($(grep OpenGL "$T/cmp.err" | head -c 200))"
"$BIN" simulate dam_break --gpu --gl egl --particles 500 --frames 1 -q -o "$T/sq_%04d.ply" 2> "$T/sq.err"; rc=$?
check '[ $rc -eq 0 ] && [ ! -s "$T/sq.err" ]' "simulate --gpu --gl egl -q: nothing on stderr ($(head -c 200 "$T/sq.err"))"
if [ "$WITH_OSMESA" = 1 ]; then
  "$BIN" render "$scene" --method spheres $small --gl osmesa -o "$T/os.png" 2> "$T/os.err"; rc=$?
  check '[ $rc -eq 0 ] && [ ! -s "$T/os.err" ]' "render --gl osmesa: no renderer line ($(head -c 200 "$T/os.err"))"
fi

# 2. --require-gpu refuses llvmpipe: exit 1, one line naming it, nothing written (-q keeps the error)
"$BIN" render "$scene" --method spheres $small --gl egl --require-gpu -o "$T/r.png" 2> "$T/r.err"; rc=$?
check 'refused "$T/r.err" --require-gpu "$T/r.png"' "render --gl egl --require-gpu refused (rc $rc: $(head -c 200 "$T/r.err"))"
"$BIN" compare "$scene" --methods spheres $small --repeat 1 --no-cache --gl egl --require-gpu -q -o "$T/rc" 2> "$T/rc.err"; rc=$?
check 'refused "$T/rc.err" --require-gpu "$T/rc"' "compare --require-gpu -q refused, no folder left (rc $rc: $(head -c 200 "$T/rc.err"))"
"$BIN" simulate dam_break --gpu --gl egl --require-gpu --particles 500 --frames 1 -o "$T/rs_%04d.ply" --stats "$T/rs.csv" \
  2> "$T/rs.err"; rc=$?
check 'refused "$T/rs.err" --require-gpu "$T/rs.csv" && [ ! -e "$T/rs_0000.ply" ]' \
  "simulate --gpu --require-gpu refused, no frame, no stats (rc $rc: $(head -c 200 "$T/rs.err"))"
if [ "$WITH_OSMESA" = 1 ]; then
  "$BIN" render "$scene" --method spheres $small --gl osmesa --require-gpu -o "$T/ro.png" 2> "$T/ro.err"; rc=$?
  check 'refused "$T/ro.err" --require-gpu "$T/ro.png"' "render --gl osmesa --require-gpu refused (rc $rc: $(head -c 200 "$T/ro.err"))"
fi
if [ "$WITH_GLFW" = 1 ] && command -v xvfb-run > /dev/null; then
  # tests/xvfb.sh: the viewer's own stderr and status, not xvfb-run's
  bash "$SRC/tests/xvfb.sh" 320x240x24 "$BIN" view "$scene" --require-gpu --frames 1 -W 64 -H 64 > /dev/null 2> "$T/rv.err"; rc=$?
  check 'refused "$T/rv.err" --require-gpu "$T/none"' "view --require-gpu refuses its GLFW window's llvmpipe (rc $rc: $(head -c 200 "$T/rv.err"))"
elif [ "$WITH_GLFW" = 1 ]; then
  echo "skip view --require-gpu: xvfb-run not installed"
  skipped="$skipped view"
fi

# 3. FLUIDSURF_REQUIRE_GPU=1 does the same, for the experiment tools too; 0 is off
FLUIDSURF_REQUIRE_GPU=1 "$BIN" render "$scene" --method spheres $small --gl egl -o "$T/e.png" 2> "$T/e.err"; rc=$?
check 'refused "$T/e.err" FLUIDSURF_REQUIRE_GPU=1 "$T/e.png"' "FLUIDSURF_REQUIRE_GPU=1 refused (rc $rc: $(head -c 200 "$T/e.err"))"
FLUIDSURF_REQUIRE_GPU=0 "$BIN" render "$scene" --method spheres $small --gl egl -q -o "$T/e0.png" 2> "$T/e0.err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/e0.png" ]' "FLUIDSURF_REQUIRE_GPU=0 is off ($(head -c 200 "$T/e0.err"))"
FLUIDSURF_REQUIRE_GPU=1 FLUIDSURF_GL=egl "$RB" --probe > "$T/rb.out" 2> "$T/rb.err"; rc=$?
check '[ $rc -eq 1 ] && [ ! -s "$T/rb.out" ] && grep -Eq "^render_bench: OpenGL: FLUIDSURF_REQUIRE_GPU=1: the OpenGL renderer is llvmpipe" "$T/rb.err"' \
  "render_bench honours FLUIDSURF_REQUIRE_GPU=1 (rc $rc: $(head -c 200 "$T/rb.err"))"

# 4. no GL context, nothing to refuse: a CPU method, the CPU simulator
"$BIN" render "$scene" --method reference $small --require-gpu -q -o "$T/cpu.png" 2> "$T/cpu.err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/cpu.png" ]' "render --method reference --require-gpu runs on the CPU ($(head -c 200 "$T/cpu.err"))"
FLUIDSURF_REQUIRE_GPU=1 "$BIN" simulate dam_break --cpu --particles 500 --frames 1 -q -o "$T/sc_%04d.ply" 2> "$T/sc.err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/sc_0001.ply" ]' "simulate --cpu under FLUIDSURF_REQUIRE_GPU=1 runs ($(head -c 200 "$T/sc.err"))"

echo "$fails failed"
[ $fails -eq 0 ] || exit 1
# a skipped check: exit 77, tests/cli.cmake's SKIP_RETURN_CODE (ctest prints "Skipped")
[ -z "$skipped" ] || { echo "skipped:$skipped"; exit 77; }
