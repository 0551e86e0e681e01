#!/usr/bin/env bash
# fluidsurf simulate: bad input gives exit 2, one stderr line "fluidsurf: ..."
# naming the problem and no file; a short run writes readable frames (CPU and
# GPU path) and a stats CSV.
set -u
BIN=$1 T=$2
rm -rf "$T"; mkdir -p "$T"
fails=0

expect_bad() { # NAME WORD ARGS...
  local name=$1 word=$2; shift 2
  rm -f "$T"/o_* "$T"/.o_* "$T"/s.csv "$T"/.s.csv*
  "$BIN" simulate "$@" > "$T/stdout" 2> "$T/stderr"
  local rc=$? lines
  lines=$(wc -l < "$T/stderr")
  if [ $rc -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q "^fluidsurf: " "$T/stderr" || ! grep -qF -- "$word" "$T/stderr"; then
    echo "FAIL $name: exit $rc, stderr ($lines lines): $(cat "$T/stderr")"; fails=$((fails + 1)); return
  fi
  if ls "$T"/o_* "$T"/.o_* "$T"/s.csv "$T"/.s.csv* >/dev/null 2>&1; then echo "FAIL $name: left a file"; fails=$((fails + 1)); return; fi
  echo "ok   $name: $(cat "$T/stderr")"
}
o="-o $T/o_%04d.bgeo"
expect_bad unknown_scene "lava" lava --frames 1 $o
expect_bad no_scene "no scene" --frames 1 $o
expect_bad no_output "no output" dam_break --frames 1
expect_bad zero_frames "--frames" dam_break --frames 0 $o
expect_bad few_particles "--particles" dam_break --particles 10 $o
expect_bad bad_eos "--eos" dam_break --eos vdw $o
expect_bad substeps_without_dt "--substeps" dam_break --substeps 10 $o
expect_bad negative_dt "--dt" dam_break --dt -0.01 $o
expect_bad fps_and_dt "--fps" dam_break --dt 0.001 --fps 30 $o
expect_bad k_without_ideal "--k" dam_break --k 100 $o
expect_bad bad_cfl "--cfl" dam_break --cfl 3 $o
expect_bad no_pattern "%d" dam_break --frames 2 -o "$T/o_.bgeo"
expect_bad bad_format "format" dam_break -o "$T/o_%04d.xyz"
expect_bad missing_dir "$T/nodir" dam_break -o "$T/nodir/o_%04d.vtk"
expect_bad unknown_option "--bogus" dam_break --bogus $o
expect_bad period_without_shake "--shake-period needs --shake" pool --shake-period 0.5 $o
expect_bad zero_shake "--shake" pool --shake 0 $o
echo '{"box": [1, 1, 0.5], "fluid": [{"min": [0, 0, 0]}]}' > "$T/bad_region.json"
echo '{"box": [1, 1, 0.5], "fluids": []}' > "$T/bad_key.json"
echo '{"box": [1, 1, 0.5], "fluid": [{"min": [2, 2, 2], "max": [3, 3, 3]}]}' > "$T/outside.json"
echo '{"box": [1, 1, 0.5], ' > "$T/malformed.json"
expect_bad json_bad_region "fluid region 0" "$T/bad_region.json" $o
expect_bad json_unknown_key "fluids" "$T/bad_key.json" $o
expect_bad json_fluid_outside "no fluid inside the box" "$T/outside.json" $o
expect_bad json_malformed "malformed JSON" "$T/malformed.json" $o
expect_bad json_missing "cannot read" "$T/missing.json" $o

# A short run on each path: frames 0..2 readable, with the count the stats report.
for path in cpu gpu; do
  rm -f "$T"/o_*
  if ! "$BIN" simulate spouts --particles 1500 --frames 2 --$path -q -o "$T/o_%04d.vtk" --stats "$T/s_$path.csv"; then
    echo "FAIL run_$path: exit $?"; fails=$((fails + 1)); continue
  fi
  n=$("$BIN" info "$T/o_0002.vtk" | awk '/^particles:/ {print $2}')
  want=$(awk -F, '$1 == "2" {print $3}' "$T/s_$path.csv")
  if [ ! -f "$T/o_0000.vtk" ] || [ -z "$n" ] || [ "$n" != "$want" ] || ! "$BIN" info "$T/o_0002.vtk" | grep -q phase; then
    echo "FAIL run_$path: frame 2 has '$n' particles, stats say '$want'"; fails=$((fails + 1)); continue
  fi
  echo "ok   run_$path: $n particles in frame 2, colours and phases written"
done
# A JSON scene: a block and a coloured ball.
echo '{"box": [1, 1, 0.5], "fluid": [{"min": [0, 0, 0], "max": [0.4, 0.6, 0.5]}, {"centre": [0.7, 0.7, 0.25], "radius": 0.15, "color": 1}]}' > "$T/ok.json"
if "$BIN" simulate "$T/ok.json" --frames 1 -q -o "$T/j_%d.bgeo" && "$BIN" info "$T/j_1.bgeo" | grep -q phase; then
  echo "ok   json_scene"
else
  echo "FAIL json_scene"; fails=$((fails + 1))
fi
# --shake: the walls move the water. A pool at rest keeps almost no kinetic energy over 3
# frames; shaken by 5 cm with a 0.2 s period it gains over 20 times as much (measured: 143x).
ke() { awk -F, '$1 == "3" {print $16}' "$1"; }
if "$BIN" simulate pool --particles 1000 --frames 3 -q --stats "$T/still.csv" &&
   "$BIN" simulate pool --particles 1000 --frames 3 -q --shake 0.05 --shake-period 0.2 --stats "$T/shaken.csv" &&
   grep -q " shake=0.05; shake_period=0.2;" "$T/shaken.csv" &&
   awk -v a="$(ke "$T/still.csv")" -v b="$(ke "$T/shaken.csv")" 'BEGIN {exit !(a != "" && b > 20 * a)}'; then
  echo "ok   shake: kinetic energy at frame 3 $(ke "$T/still.csv") still, $(ke "$T/shaken.csv") shaken"
else
  echo "FAIL shake: kinetic energy at frame 3 '$(ke "$T/still.csv")' still, '$(ke "$T/shaken.csv")' shaken"; fails=$((fails + 1))
fi
"$BIN" simulate --help | grep -q "usage: fluidsurf simulate" || { echo "FAIL help"; fails=$((fails + 1)); }
echo "$fails failure(s)"
[ $fails -eq 0 ]
