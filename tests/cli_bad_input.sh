#!/usr/bin/env bash
# Every kind of bad input: exit status 2, exactly one stderr line starting with
# "fluidsurf: " and naming the culprit, no output file, an existing output untouched.
set -u
BIN=$1 DATA=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
vtk=$DATA/dam_break_frame_23_24389_particles.vtk
bgeo=$DATA/dam_break_frame_9_6859_particles.bgeo

# expect_bad NAME WORD ARGS...: WORD must appear in the error line.
expect_bad() {
  local name=$1 word=$2; shift 2
  n=$((n + 1))
  rm -f "$T/out.png" "$T/out.exr" "$T"/.out*
  "$BIN" "$@" > "$T/stdout" 2> "$T/stderr"
  local rc=$? lines
  lines=$(wc -l < "$T/stderr")
  if [ $rc -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q "^fluidsurf: " "$T/stderr" || ! grep -qF -- "$word" "$T/stderr"; then
    echo "FAIL $name: exit $rc, stderr ($lines lines): $(cat "$T/stderr")"; fails=$((fails + 1)); return
  fi
  if ls "$T"/out.* "$T"/.out* >/dev/null 2>&1; then echo "FAIL $name: left an output file"; fails=$((fails + 1)); return; fi
  echo "ok   $name: $(cat "$T/stderr")"
}

render() { expect_bad "$1" "$2" render "${@:3}" -o "$T/out.png"; }

: > "$T/empty.vtk"
head -c 4000 "$vtk" > "$T/truncated.vtk"
gzip -dc "$bgeo" | head -c 100000 | gzip > "$T/truncated.bgeo"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > "$T/truncated.ply"
head -c 5000 /dev/urandom >> "$T/truncated.ply"
printf 'NOTAVTKFILE\nhello\n' > "$T/magic.vtk"
printf 'x,y,z\n0,0,0\n1,nan,0\n' > "$T/nan.csv"
printf 'x,y,z\n0,0,0\ninf,1,0\n' > "$T/inf.csv"
printf 'ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > "$T/zero.ply"
printf '{"particles": "x.vtk", "radius": 0.02,' > "$T/malformed.json"
printf '{"particles": "%s", "radius": -0.025}' "$vtk" > "$T/negradius.json"
printf '{"particles": "%s", "radiuss": 0.025}' "$vtk" > "$T/typo.json"
printf '{"particles": "%s", "camera": {"width": 0}}' "$vtk" > "$T/zerowidth.json"
printf '{"particles": "%s", "methods": {"reference": {"nope": 1}}}' "$vtk" > "$T/badparam.json"

render missing_file "missing.vtk" "$T/missing.vtk"
render empty_file "empty.vtk" "$T/empty.vtk"
render truncated_vtk "truncated.vtk" "$T/truncated.vtk"
render truncated_bgeo "truncated.bgeo" "$T/truncated.bgeo"
render truncated_ply "truncated.ply" "$T/truncated.ply"
render wrong_magic "magic.vtk" "$T/magic.vtk"
render nan_position "nan.csv" "$T/nan.csv"
render inf_position "inf.csv" "$T/inf.csv"
render zero_particles "zero.ply" "$T/zero.ply"
render unknown_extension "data.xyzw" "$T/data.xyzw"
render negative_radius_flag "--radius" "$vtk" --radius -0.025
render negative_radius_scene "radius" "$T/negradius.json"
render zero_width_flag "-W" "$vtk" -W 0
render absurd_width_flag "-W" "$vtk" -W 100000
render absurd_size "too large" "$vtk" -W 16384 -H 16384
render zero_width_scene "width" "$T/zerowidth.json"
render malformed_json "malformed JSON" "$T/malformed.json"
render unknown_scene_key "radiuss" "$T/typo.json"
render unknown_method "nosuchmethod" "$vtk" --method nosuchmethod
render unknown_param "nope" "$T/badparam.json"
render unknown_param_flag "bogus" "$vtk" --set reference.bogus=1
render bad_param_value "step_min" "$vtk" --set reference.step_min=abc
render param_out_of_range "step_min" "$vtk" --set reference.step_min=-5
render set_unknown_method "nomethod" "$vtk" --set nomethod.x=1
expect_bad bad_output_ext "out.txt" render "$vtk" -o "$T/out.txt"
render unknown_option "--frobnicate" "$vtk" --frobnicate
render bad_appearance "--appearance frob" "$vtk" --method surfels --appearance frob
render no_own_appearance "spheres" "$vtk" --method spheres --appearance own
render export_unsupported "exports nothing" "$vtk" --method spheres --export "$T/out.vdb"
expect_bad export_bad_ext "out.txt" render "$vtk" --method surfels -W 16 -H 16 --export "$T/out.txt"
expect_bad export_missing_dir "nodir" render "$vtk" --method surfels -W 16 -H 16 --export "$T/nodir/out.vdb"
render bad_object "cube" "$vtk" --method surfels --set surfels.object=cube
expect_bad info_missing "missing.bgeo" info "$T/missing.bgeo"
expect_bad convert_bad_target "out.xyz9" convert "$vtk" -o "$T/out.xyz9"
expect_bad convert_onto_input "overwrite" convert "$T/nan.csv" -o "$T/nan.csv"
expect_bad no_command "unknown command" frobnicate

# A failed render must not clobber an existing output.
n=$((n + 1))
echo precious > "$T/keep.png"
"$BIN" render "$T/truncated.vtk" -o "$T/keep.png" 2>/dev/null
if [ "$(cat "$T/keep.png")" != precious ]; then echo "FAIL existing output clobbered"; fails=$((fails + 1)); else echo "ok   existing output kept"; fi
if ls -a "$T" | grep -q '\.tmp'; then echo "FAIL temporary files left: $(ls -a "$T" | grep tmp)"; fails=$((fails + 1)); fi

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
