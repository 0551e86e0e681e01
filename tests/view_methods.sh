#!/usr/bin/env bash
# Every registered method shows the fluid in the viewer, in both modes
# (tests/view.cmake runs this under xvfb-run, ctest cli_view_methods):
#   scene:     a scene file that plays (experiments/scenes/slab_sequence.json,
#              frames 0-9, so every displayed frame uploads a new particle set)
#              and a still one (dam_break.json, 24k SPlisHSPlasH particles);
#   simulate:  --simulate dam_break --particles 2000 on the CPU path, playing.
# VIEW_MODES (default all three) picks some (the sanitizer build: tests/view.cmake).
# The methods come from `fluidsurf methods` (a line "NAME — description" per
# method, in registry order), so a new method is covered without editing this
# file; key N selects the N-th (--method NAME from the 10th on). Each run
# starts with the first method, switches at frame 1 and takes the screenshot
# at frame 2, after the method has received at least one new particle set
# (the next frame of the scene, one more simulator step) since it was created.
#
# "Fluid visible": at least MIN_WATER (5%) of the screenshot's pixels look
# like water under the shared shading, blue minus red above 20/255
# (tests/png_water.py, the criterion of tests/view.sh). Measured at 160x120:
# the empty views (checker floor, sky, the simulator's orange container) have
# 0.0000; the fluid covers 0.12-0.18 with every method in every view here
# (once the viewer uploads correctly). A method with a "grid_res" parameter
# runs with grid_res=64 to keep the test quick.
#
# A method that cannot render the current frame must say why on stderr and in
# the title bar and the viewer must go on: a scene lit from below makes
# surfels' caustics fail ("the light must come from above") on every frame,
# independently of the particles' source; skipped when no method is named
# surfels or surfels has no number key: then, when nothing failed, the test exits
# 77, which tests/view.cmake declares SKIP_RETURN_CODE (ctest prints "Skipped").
set -u
BIN=$1 SRC=$2 T=$3
PY=${PYTHON3:-python3}
MIN_WATER=0.05
fails=0 n=0 skipped=
pass() { n=$((n + 1)); }
fail() { echo "FAIL $*"; fails=$((fails + 1)); n=$((n + 1)); }
rm -rf "$T"; mkdir -p "$T"; cd "$T" || exit 1
scenes=$SRC/experiments/scenes
WIN=(-W 160 -H 120)

# the registry, in order: the first word of each line "NAME — description"
mapfile -t methods < <("$BIN" methods | awk '/^[^ ]/ && $2 == "—" { print $1 }')
if [ ${#methods[@]} -eq 0 ]; then
  echo "FAIL no methods parsed from 'fluidsurf methods'"
  exit 1
fi
echo "methods: ${methods[*]}"
# quick: a method with a density grid ("grid_res", 256 by default: 2-6 s a frame
# on llvmpipe) builds a 64-point one; the fluid's visibility does not depend on it
quick=()
for m in $("$BIN" methods | awk '/^[^ ]/ { m = $1 } /^    grid_res  *=/ { print m }'); do
  quick+=(--set "$m.grid_res=64")
done

# select I NAME: the viewer arguments and events that pick the I-th method (1-based)
select_method() {
  if [ "$1" -le 9 ]; then sel_args=(); sel_ev="frame 1 key $1; "
  else sel_args=(--method "$2"); sel_ev=""; fi
}

# shoot MODE I NAME ARGS...: one viewer run showing method I at frame 2
shoot() {
  local mode=$1 i=$2 m=$3; shift 3
  select_method "$i" "$m"
  local out=$mode-$m
  local t0=$SECONDS
  "$BIN" view "$@" "${WIN[@]}" "${quick[@]}" "${sel_args[@]}" -v --events "${sel_ev}frame 2 screenshot $out.png; frame 3 quit" \
    > /dev/null 2> "$out.err"
  echo $? > "$out.rc"
  echo "$mode $m: $((SECONDS - t0)) s"
}

read -ra modes <<< "${VIEW_MODES:-sequence still simulate}"
declare -A input=([sequence]="$scenes/slab_sequence.json" [still]="$scenes/dam_break.json"
  [simulate]="--simulate dam_break --particles 2000")
for i in "${!methods[@]}"; do
  for mode in "${modes[@]}"; do
    # shellcheck disable=SC2086 # the simulator's input is three words
    shoot "$mode" $((i + 1)) "${methods[$i]}" ${input[$mode]}
  done
done

# one python process reads every screenshot
"$PY" "$SRC/tests/png_water.py" ./*.png > water.txt 2> water.err
for mode in "${modes[@]}"; do
  for m in "${methods[@]}"; do
    out=$mode-$m
    # the reason a run gave up, if any: its stderr minus the title bar and the banner
    why=$(grep -v '^fluidsurf view |\|^fluidsurf: view: \|^fluidsurf: screenshot ' "$out.err" | head -2 | tr '\n' ' ')
    rc=$(cat "$out.rc")
    frac=$(awk -v f="./$out.png" '$1 == f && $2 == 160 && $3 == 120 { print $4 }' water.txt)
    if [ "$rc" != 0 ] || [ ! -s "$out.png" ]; then
      fail "$mode $m: exit $rc, no screenshot${why:+: $why}"
    elif ! grep -q "^fluidsurf view | $m (" "$out.err"; then
      fail "$mode $m: the title bar never names $m (does key N pick the N-th method?): $(grep -m2 '^fluidsurf view' "$out.err" | tail -1)"
    elif [ -z "$frac" ] || ! awk -v a="$frac" -v b="$MIN_WATER" 'BEGIN { exit !(a >= b) }'; then
      fail "$mode $m: fluid not visible: ${frac:-?} of the pixels are water, need >= $MIN_WATER${why:+; stderr: $why}"
    else
      echo "ok   $mode $m: water $frac"
      pass
    fi
  done
done

# a method that cannot render says why: stderr and title bar, and the viewer goes on
si=0
for i in "${!methods[@]}"; do [ "${methods[$i]}" = surfels ] && si=$((i + 1)); done
if [ $si -eq 0 ]; then
  echo "skip: no method surfels, no failing case to provoke"
  skipped="no method surfels"
elif [ $si -gt 9 ]; then
  echo "skip: surfels is not on a number key"
  skipped="surfels is not on a number key"
else
  cat > lit_from_below.json << 'J'
{"description": "synthetic box lit from below: surfels' caustics refuse it",
 "particles": {"synthetic": "box", "jitter": 0.1, "seed": 1}, "radius": 0.025,
 "light": {"direction": [0.3, -0.9, 0.3]}}
J
  reason='light must come from above'
  "$BIN" view lit_from_below.json "${WIN[@]}" "${quick[@]}" --set surfels.caustics=on -v \
    --events "frame 1 key $si; frame 3 key 1; frame 4 screenshot after.png; frame 5 quit" > /dev/null 2> fail.err
  echo "lit from below: exit $?"
  [ "$(grep -v '^fluidsurf view |' fail.err | grep -c "$reason")" -eq 1 ] && pass ||
    fail "surfels, light from below: no one-line reason '$reason' on stderr: $(grep -v '^fluidsurf view |' fail.err | tr '\n' ' ')"
  grep "^fluidsurf view | surfels " fail.err | grep -q "$reason" && pass ||
    fail "surfels, light from below: the title bar does not say '$reason': $(grep '^fluidsurf view | surfels' fail.err | head -1)"
  frac=$("$PY" "$SRC/tests/png_water.py" after.png 2> /dev/null | awk '{ print $4 }')
  [ -n "$frac" ] && awk -v a="$frac" -v b="$MIN_WATER" 'BEGIN { exit !(a >= b) }' && pass ||
    fail "surfels, light from below: the viewer did not go on to show ${methods[0]} (key 1) with water: ${frac:-no screenshot}"
fi
echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ] || exit 1
[ -z "$skipped" ] || { echo "skipped: the failing-method case ($skipped)"; exit 77; }
