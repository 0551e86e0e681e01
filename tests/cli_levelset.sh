#!/usr/bin/env bash
# The levelset method from the CLI (a build with OpenVDB): the bundled dam break
# (experiments/scenes/dam_break.json) against the reference through compare and
# diff at 128x128, the .vdb export (temp + rename; vdb_print reads it when
# libopenvdb-tools is installed), refused exports and parameters (exit 2, one line).
# usage: tests/cli_levelset.sh BIN SRC OUT
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
scene=$SRC/experiments/scenes/dam_break.json
"$BIN" methods | grep -q '^levelset' ; check '[ $? -eq 0 ]' "levelset is registered"
"$BIN" compare "$scene" --methods levelset -W 128 -H 128 --repeat 1 -q --no-cache -o "$T/cmp" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/cmp/levelset.exr" ] && [ -s "$T/cmp/reference.exr" ]' "compare levelset at 128x128 ($(head -c 200 "$T/err"))"
# spheres of 2r stand about r outside the iso-surface, nearer the eye; the splash's
# lone particles are spheres in the level set and nothing in the reference
"$BIN" diff "$T/cmp/levelset.exr" "$T/cmp/reference.exr" --fail-iou 0.7 --fail-depth-r 8 --fail-normal-deg 35 > "$T/diff.txt" 2>&1; rc=$?
cat "$T/diff.txt"
check '[ $rc -eq 0 ]' "levelset vs reference: IoU >= 0.7, |depth bias| and rmse <= 8 r, normal mean <= 35 deg"
bias=$(awk '$1 == "depth_bias_r" {print $2}' "$T/diff.txt")
check 'awk -v b="$bias" "BEGIN { exit !(b < 0) }"' "the level set is nearer the eye than the iso-surface (bias $bias r)"
# the export
"$BIN" render "$scene" --method levelset -W 32 -H 32 -q --export "$T/ls.vdb" -o "$T/ls.png" 2> "$T/err"; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/ls.vdb" ] && [ -s "$T/ls.png" ]' "render --export ls.vdb ($(head -c 200 "$T/err"))"
if command -v vdb_print > /dev/null; then
  vdb_print "$T/ls.vdb" > "$T/print.txt" 2>&1; rc=$?
  check '[ $rc -eq 0 ] && grep -q "surface" "$T/print.txt" && grep -q "float" "$T/print.txt"' "vdb_print reads the level set ($(tr '\n' ' ' < "$T/print.txt" | head -c 200))"
else
  echo "skip vdb_print (libopenvdb-tools) not installed"
fi
refused() { # exit 2, one line on stderr, no output
  local what=$1 out=$2; shift 2
  "$BIN" "$@" > /dev/null 2> "$T/err"; local rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && [ ! -e "$out" ]' "$what refused (rc $rc: $(head -c 200 "$T/err"))"
}
refused "--export .ply" "$T/x.ply" render "$scene" --method levelset -W 16 -H 16 -q --export "$T/x.ply" -o "$T/x.png"
for bad in radius=0 voxel=0 voxel=-0.5 half_width=0 smooth=median radius=0.5; do
  refused "levelset.$bad" "$T/bad.png" render "$scene" --method levelset -W 16 -H 16 -q --set "levelset.$bad" -o "$T/bad.png"
done
"$BIN" render "$scene" --method levelset -W 16 -H 16 -q --set levelset.radius=0 -o "$T/bad.png" 2> "$T/err"
check 'grep -q "radius" "$T/err" && grep -q "0.01" "$T/err"' "the refusal names the parameter and its range ($(cat "$T/err"))"
check '[ -z "$(find "$T" -name ".*.tmp*")" ]' "no temporary files left"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
