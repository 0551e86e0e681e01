#!/usr/bin/env bash
# A bare particle file's scene from the command line: --up auto|x|y|z (auto picks
# the axis and says so in a note), the field options, and where r came from, all
# in every output's provenance (fluidsurf:up, fluidsurf:field, fluidsurf:r_source).
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
n=$(($(grep -c '|| fail' "$0") - 1)) # minus this line

# An ASCII PLY of a jittered lattice, nx x ny x nz at spacing 2r = 0.05, with a
# comment radius when $5 is given; $6 adds a column (a pile-up) of height $7 on axis $6;
# $8 lifts each (x, y) column of the lattice by up to $8 spacings along z (a rough bottom).
ply() { # out nx ny nz [radius] [column-axis column-height] [roughness]
  awk -v nx="$2" -v ny="$3" -v nz="$4" -v rad="${5:-}" -v ax="${6:-}" -v hc="${7:-0}" -v rough="${8:-0}" 'BEGIN {
    srand(7); n = 0
    for (i = 0; i < nx; i++) for (j = 0; j < ny; j++) { lift = rough * rand()
      for (k = 0; k < nz; k++) p[n++] = i " " j " " (k + lift) }
    if (ax != "") for (a = 0; a < 3; a++) for (b = 0; b < 3; b++) for (c = 0; c < hc; c++)
      p[n++] = (ax == "y" ? a " " c " " b : a " " b " " c)
    print "ply"; print "format ascii 1.0"; if (rad != "") print "comment radius " rad
    print "element vertex " n; print "property float x"; print "property float y"; print "property float z"
    print "end_header"
    for (m = 0; m < n; m++) { split(p[m], q, " ")
      printf "%.5f %.5f %.5f\n", q[1] * 0.05 + 0.002 * rand(), q[2] * 0.05 + 0.002 * rand(), q[3] * 0.05 + 0.002 * rand() }
  }' > "$1"
}
attr() { iinfo -v "$1" 2>/dev/null | sed -n "s/^ *fluidsurf:$2: \"\(.*\)\"$/\1/p"; }
render() { "$BIN" render "$@" --method reference -W 32 -H 24; }

ply "$T/pool_z.ply" 24 16 4         # thin along z: a z-up pool
ply "$T/pool_y.ply" 24 4 16         # thin along y
ply "$T/cube.ply" 10 10 10          # no axis stands out: y, the convention
ply "$T/pile_z.ply" 20 20 3 "" z 20 2 # as wide as tall on every axis, the mass at the low end of z, no flat floor
ply "$T/floor_z.ply" 20 20 3 "" z 20  # the same on a flat floor
ply "$T/pool_r.ply" 24 4 16 0.03    # a radius in the file

render "$T/pool_z.ply" -o "$T/pool_z.exr" 2> "$T/pool_z.err" || fail "render pool_z"
grep -q "^fluidsurf: note: .*pool_z.ply: up is z (auto: a floor: 25.0% of the particles lie within r of its low end, 4.00 times the 6.2% along y; set --up)$" "$T/pool_z.err" ||
  fail "no note naming up = z: $(cat "$T/pool_z.err")"
grep -q "^fluidsurf: note: .*pool_z.ply gives no particle radius: r = .* estimated from its spacing" "$T/pool_z.err" ||
  fail "no note of the estimated r on its own line: $(cat "$T/pool_z.err")"
[ "$(attr "$T/pool_z.exr" up)" = "z;auto" ] || fail "pool_z: up provenance '$(attr "$T/pool_z.exr" up)', not z;auto"
[ "$(attr "$T/pool_z.exr" r_source)" = estimated ] || fail "pool_z: r_source '$(attr "$T/pool_z.exr" r_source)', not estimated"
# the framed camera stands upright along z
attr "$T/pool_z.exr" camera | grep -q ';up=0,0,1;' || fail "pool_z: camera not z-up: $(attr "$T/pool_z.exr" camera)"

render "$T/pool_y.ply" -q -o "$T/pool_y.exr" || fail "render pool_y"
[ "$(attr "$T/pool_y.exr" up)" = "y;auto" ] || fail "pool_y: up '$(attr "$T/pool_y.exr" up)', not y;auto"
render "$T/cube.ply" -o "$T/cube.exr" 2> "$T/cube.err" || fail "render cube"
[ "$(attr "$T/cube.exr" up)" = "y;auto" ] || fail "cube: up '$(attr "$T/cube.exr" up)', not y;auto"
grep -q "up is y (auto: no axis stands out; y, the usual convention" "$T/cube.err" || fail "cube note: $(cat "$T/cube.err")"
render "$T/pile_z.ply" -o "$T/pile_z.exr" 2> "$T/pile_z.err" || fail "render pile_z"
[ "$(attr "$T/pile_z.exr" up)" = "z;auto" ] || fail "pile_z: up '$(attr "$T/pile_z.exr" up)', not z;auto ($(cat "$T/pile_z.err"))"
grep -q "up is z (auto: the particles pile up at its low end, skewness" "$T/pile_z.err" || fail "pile_z note: $(cat "$T/pile_z.err")"
render "$T/floor_z.ply" -o "$T/floor_z.exr" 2> "$T/floor_z.err" || fail "render floor_z"
grep -q "up is z (auto: a floor: " "$T/floor_z.err" || fail "floor_z note: $(cat "$T/floor_z.err")"

# --up wins, says nothing; -q silences the notes
render "$T/pool_z.ply" --up x -o "$T/up_x.exr" 2> "$T/up_x.err" || fail "render --up x"
[ "$(attr "$T/up_x.exr" up)" = "x;option" ] || fail "--up x: up '$(attr "$T/up_x.exr" up)'"
! grep -q "up is" "$T/up_x.err" || fail "--up x still printed an auto note"
render "$T/pool_z.ply" -q -o "$T/quiet.exr" 2> "$T/quiet.err" || fail "render -q"
[ ! -s "$T/quiet.err" ] || fail "-q printed: $(cat "$T/quiet.err")"
"$BIN" render "$T/pool_z.ply" --up w -o "$T/bad.exr" 2> "$T/bad.err"; [ $? = 2 ] || fail "--up w did not exit 2"
[ ! -e "$T/bad.exr" ] && [ "$(wc -l < "$T/bad.err")" = 1 ] || fail "--up w: output left or not one line: $(cat "$T/bad.err")"
# a scene file keeps its up (y unless it says), and may say auto
printf '{"particles": "pool_z.ply", "radius": 0.025}\n' > "$T/scene.json"
printf '{"particles": "pool_z.ply", "radius": 0.025, "up": "auto"}\n' > "$T/scene_auto.json"
render "$T/scene.json" -q -o "$T/scene.exr" || fail "render scene.json"
[ "$(attr "$T/scene.exr" up)" = "y;default" ] || fail "scene.json: up '$(attr "$T/scene.exr" up)', not y;default"
[ "$(attr "$T/scene.exr" r_source)" = scene ] || fail "scene.json: r_source '$(attr "$T/scene.exr" r_source)', not scene"
render "$T/scene_auto.json" -q -o "$T/scene_auto.exr" || fail "render scene_auto.json"
[ "$(attr "$T/scene_auto.exr" up)" = "z;auto" ] || fail "scene up auto: '$(attr "$T/scene_auto.exr" up)'"

# r: the option, the file's, the scene's (above), the estimate (above)
render "$T/pool_z.ply" -q --radius 0.02 -o "$T/r_opt.exr" || fail "render --radius"
[ "$(attr "$T/r_opt.exr" r_source)" = option ] && [ "$(attr "$T/r_opt.exr" r)" = 0.0199999996 ] ||
  fail "--radius 0.02: r_source '$(attr "$T/r_opt.exr" r_source)', r '$(attr "$T/r_opt.exr" r)'"
render "$T/pool_r.ply" -q -o "$T/r_file.exr" || fail "render pool_r"
[ "$(attr "$T/r_file.exr" r_source)" = file ] && [ "$(attr "$T/r_file.exr" r)" = 0.0299999993 ] ||
  fail "radius in the file: r_source '$(attr "$T/r_file.exr" r_source)', r '$(attr "$T/r_file.exr" r)'"
for cmd in render compare mesh view; do
  "$BIN" $cmd --help | grep -q "else 0.025" && fail "$cmd --help still says r defaults to 0.025"
  "$BIN" $cmd --help | grep -q "estimated from" || fail "$cmd --help does not say r is estimated"
done

# the field on the command line: in the provenance, and a different scene for diff and the caches
render "$T/pool_z.ply" -q --iso 0.3 --kernel poly6 --support 3 --volume-scale 1.2 -o "$T/field.exr" || fail "render field options"
[ "$(attr "$T/field.exr" field)" = "kernel=poly6;support=3r;iso=0.300000012;volume_scale=1.20000005" ] ||
  fail "field provenance: '$(attr "$T/field.exr" field)'"
[ "$(attr "$T/field.exr" scene_hash)" != "$(attr "$T/pool_z.exr" scene_hash)" ] || fail "field options left the scene hash as it was"
"$BIN" diff "$T/field.exr" "$T/pool_z.exr" > /dev/null 2> "$T/diff.err"
grep -q "scene" "$T/diff.err" || fail "diff of two fields gave no scene warning: $(cat "$T/diff.err")"
render "$T/pool_z.ply" -q --iso 0 -o "$T/bad_iso.exr" 2> "$T/bad_iso.err"; [ $? = 2 ] && [ ! -e "$T/bad_iso.exr" ] ||
  fail "--iso 0 was not refused with exit 2"
# mesh takes the field too (no up: it has no camera, and says nothing of one)
"$BIN" mesh "$T/pool_z.ply" --iso 0.3 -o "$T/pool.ply" 2> "$T/mesh.err" || fail "mesh --iso"
! grep -q "up is" "$T/mesh.err" || fail "mesh printed an up note"
"$BIN" mesh "$T/pool_z.ply" --up z -o "$T/pool2.ply" 2> /dev/null; [ $? = 2 ] || fail "mesh accepted --up"
# compare: the same options
"$BIN" compare "$T/pool_z.ply" --methods spheres -W 32 -H 24 --repeat 1 --no-cache -q --up x --iso 0.5 -o "$T/cmp" ||
  fail "compare with --up and --iso"
[ "$(attr "$T/cmp/spheres.exr" up)" = "x;option" ] || fail "compare --up x: '$(attr "$T/cmp/spheres.exr" up)'"
attr "$T/cmp/spheres.exr" field | grep -q "iso=0.5;" || fail "compare --iso 0.5: '$(attr "$T/cmp/spheres.exr" field)'"

echo "cli_scene_axes: $((n - fails)) of $n checks passed"
[ "$fails" = 0 ]
