#!/usr/bin/env bash
# fluidsurf view end to end, under Xvfb (tests/view.cmake runs it through
# xvfb-run): scripted input drives the real window and input handlers; the
# screenshots must exist at the window size, show water (pixels much bluer than
# the grey floor and sky) and change when the camera orbits, the method
# switches, the scale changes or the container is pushed; paused frames must
# not change. Bad input: exit 2 with one line.
set -u
BIN=$1 SRC=$2 T=$3
fails=0 n=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
n=$(($(grep -c '|| fail' "$0") - 1)) # minus this line
rm -rf "$T"; mkdir -p "$T"; cd "$T" || exit 1
scene=$SRC/experiments/scenes/dam_break.json
# One oiiotool call per PNG (each costs ~0.3 s): it exists, is 160x120, is not
# uniform, and at least 2% of its pixels are water: B - R > 0.08 (the floor
# and the sky are grey), counted as the mean of a 0/1 mask.
shot_ok() {
  [ -s "$1" ] || return 1
  oiiotool "$1" --printstats --chsum:weight=-1,0,1 --subc 0.08 --clamp:min=0 --mulc 1000 --clamp:max=1 \
    --printstats > stats.txt 2>&1 || return 1
  grep -q "160 x  *120" stats.txt && grep -q "Constant: No" stats.txt &&
    awk '/Avg/ { a = $3 } END { exit !(a > 0.02) }' stats.txt; }
differ() { ! idiff "$1" "$2" > /dev/null 2>&1; }
same() { idiff "$1" "$2" > /dev/null 2>&1; }
one_line_exit2() { # command...: exit 2, exactly one "fluidsurf: " line on stderr
  "$@" > /dev/null 2> err.txt; local rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q '^fluidsurf: ' err.txt; }

# 1. a scene: orbit, method switch (2 = reference), pan + zoom + smaller scale,
# surfels in its own appearance; through a script file
cat > script.txt << 'S'
# frame N action
frame 1 screenshot a.png
frame 0 key s                      # numbered name in the working folder
frame 2 drag 80 60 120 70          # orbit
frame 3 screenshot b.png
frame 4 key 2                      # reference
frame 5 screenshot c.png
frame 6 drag 80 60 90 60 right     # pan
frame 6 scroll 1
frame 6 key minus
frame 7 screenshot d.png
frame 8 key 5; frame 8 key o       # surfels, own appearance
frame 9 screenshot e.png
frame 10 quit
S
"$BIN" view "$scene" -W 160 -H 120 -v --script script.txt 2> scene.err || fail "scene run: $(cat scene.err)"
for f in a b c d e; do shot_ok $f.png || fail "$f.png: missing, not 160x120, uniform or without water"; done
grep -q '^fluidsurf: screenshot a.png (160x120)' scene.err || fail "the screenshot is not named on stderr"
grep -q '^fluidsurf: screenshot fluidsurf_view_001.png (160x120)' scene.err && cmp -s a.png fluidsurf_view_001.png ||
  fail "key S: no numbered screenshot equal to the scripted one of the next (same) frame"
grep -q '^fluidsurf view | spheres (shared) | [0-9.]* ms | .* | scale 1.00 (160x120) | frame 0 ' scene.err ||
  fail "title bar: $(grep -m1 '^fluidsurf view' scene.err)"
grep -q '^fluidsurf view | surfels (own) | .* | scale 0.80 (128x96) | ' scene.err || fail "title bar after keys 5, o and minus"
differ a.png b.png || fail "orbiting did not change the image"
differ b.png c.png || fail "switching to reference did not change the image"
differ c.png d.png || fail "pan, zoom and scale did not change the image"
differ d.png e.png || fail "surfels' own appearance did not change the image"

# 2. the simulator (CPU path), paused: frames stay; then playing, a shift-drag
# pushes the container: the result differs from the same run without the drag
ev="frame 1 screenshot p1.png; frame 3 screenshot p2.png; frame 4 key space; frame 9 screenshot s.png; frame 10 quit"
drag="frame 5 drag 80 60 140 60 shift"
sim=(view --simulate dam_break --particles 2000 -W 160 -H 120 --paused)
"$BIN" "${sim[@]}" -v --events "$ev; $drag" 2> sim.err || fail "simulator run: $(cat sim.err)"
mv s.png s_drag.png
"$BIN" "${sim[@]}" --events "$ev" 2> sim2.err || fail "simulator run without drag: $(cat sim2.err)"
for f in p1 p2 s s_drag; do shot_ok $f.png || fail "$f.png: missing, not 160x120, uniform or without water"; done
grep -q '| t = 0.000 s, 2[0-9]* particles, paused | #3$' sim.err || fail "simulator title bar: $(grep -m4 '^fluidsurf view' sim.err | tail -1)"
grep -q '| t = 0.100 s, 2[0-9]* particles | #9$' sim.err || fail "simulated time in the title: $(grep '#9$' sim.err)"
same p1.png p2.png || fail "paused, the simulation still moved"
differ p1.png s.png || fail "playing, the simulation did not move"
differ s.png s_drag.png || fail "dragging the container changed nothing"

# 3. the GPU simulation path with a ctrl-drag, and an N (one frame) step
"$BIN" view --simulate dam_break --gpu --particles 2000 -W 160 -H 120 --paused \
  --events "frame 1 screenshot g0.png; frame 2 key n; frame 2 drag 80 60 120 60 ctrl; frame 3 key n; frame 4 screenshot g1.png; frame 5 quit" \
  2> gpu.err || fail "GPU simulator run: $(cat gpu.err)"
shot_ok g0.png && shot_ok g1.png || fail "GPU path screenshots missing or without water"
differ g0.png g1.png || fail "GPU path: stepping did not move the fluid"

# 4. bad input
one_line_exit2 "$BIN" view "$T/nonexistent.json" || fail "unknown scene: $(cat err.txt)"
one_line_exit2 "$BIN" view "$scene" --events "frame 1 jump" || fail "unknown action: $(cat err.txt)"
one_line_exit2 "$BIN" view "$scene" --events "frame x key 1" || fail "bad frame: $(cat err.txt)"
one_line_exit2 "$BIN" view "$scene" --events "frame 1 key nokey" || fail "bad key name: $(cat err.txt)"
one_line_exit2 "$BIN" view "$scene" --script "$T/nonexistent.txt" || fail "missing script: $(cat err.txt)"
one_line_exit2 "$BIN" view --simulate nosuch || fail "unknown simulator scene: $(cat err.txt)"
one_line_exit2 "$BIN" view "$scene" --set spheres.nosuch=1 || fail "unknown parameter: $(cat err.txt)"
one_line_exit2 "$BIN" view || fail "no input: $(cat err.txt)"
"$BIN" view "$scene" --events "frame 1 key 1; frame 2 fly" 2>&1 | grep -q -- '--events:2: unknown action' ||
  fail "a bad action does not name its position"
"$BIN" view --help | grep -q usage || fail "view --help"
echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
