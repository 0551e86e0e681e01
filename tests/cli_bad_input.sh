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
  # one line of valid UTF-8 text, whatever bytes the input held
  if [ $rc -ne "${want_rc:-2}" ] || [ "$lines" -ne 1 ] || ! grep -q "^fluidsurf: " "$T/stderr" || ! grep -qF -- "$word" "$T/stderr" ||
     ! iconv -f UTF-8 -t UTF-8 "$T/stderr" > /dev/null 2>&1; then
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
# an unknown method lists the names, as --set does (issue 53: "see 'fluidsurf methods'")
render unknown_method_lists "unknown method 'nosuchmethod' (methods: spheres, reference" "$vtk" --method nosuchmethod
render unknown_param "nope" "$T/badparam.json"
render unknown_param_flag "bogus" "$vtk" --set reference.bogus=1
render bad_param_value "step_min" "$vtk" --set reference.step_min=abc
render param_out_of_range "step_min" "$vtk" --set reference.step_min=-5
render set_unknown_method "nomethod" "$vtk" --set nomethod.x=1
# a setting for a method that does not run was ignored without a word (issue 53)
render set_method_not_run "aniso_ssf does not run here (what runs: raycast_pca)" "$vtk" --method raycast_pca --set aniso_ssf.sigma=2
expect_bad compare_set_not_run "aniso_ssf does not run here (what runs: spheres, reference)" compare "$vtk" --methods spheres --set aniso_ssf.sigma=2 -o "$T/out"
expect_bad compare_set_analytic_only "reference does not run here (what runs: spheres)" compare "$DATA/../../scenes/box.json" --methods spheres --reference analytic --set reference.step_min=0.5 -o "$T/out"
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

# ---- every reader: absurd counts, forged headers, wrong content
printf 'ply\nformat binary_little_endian 1.0\nelement pad 18446744073709551615\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > "$T/noprops.ply"
printf 'ply\nformat ascii 1.0\ncomment radius 1e30\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n' > "$T/hugeradius.ply"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > "$T/hugecount.ply"
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n' > "$T/noz.ply"
printf 'ply\nformat utf8 1.0\nend_header\n' > "$T/badformat.ply"
printf '# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\nPOINTS 1000000000 float\n' > "$T/hugecount.vtk"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 100000 100000 100000\n' > "$T/structured.vtk"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 1 1 1\nVERTICES 2 1000000000\n' > "$T/hugecells.vtk"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 1 1 1\nPOINT_DATA 3\n' > "$T/pointdata.vtk"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 bit\n0 0 0 1 1 1\n' > "$T/bittype.vtk"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 1 1 1\nFROB\n' > "$T/badsection.vtk"
printf '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n<UnstructuredGrid>\n<Piece NumberOfPoints="1000000000000" NumberOfCells="0">\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n' > "$T/hugecount.vtu"
printf 'not xml at all\n' > "$T/notxml.vtu"
head -c 37 /dev/zero > "$T/odd.raw"
printf 'x,y,z\n' > "$T/headeronly.csv"
printf 'x,y\n0,0\n' > "$T/noz.csv"
printf 'NOTBGEO' > "$T/magic.bgeo"
printf 'not a vdb file' > "$T/magic.vdb"
mkdir -p "$T/folder.ply"
render noprops_huge_count "no properties" "$T/noprops.ply"
render ply_huge_radius "radius" "$T/hugeradius.ply"
render ply_huge_count "4000000000" "$T/hugecount.ply"
render ply_no_z "lacks x, y or z" "$T/noz.ply"
render ply_bad_format "utf8" "$T/badformat.ply"
render vtk_huge_count "truncated VTK file" "$T/hugecount.vtk"
render vtk_structured_points "STRUCTURED_POINTS" "$T/structured.vtk"
render vtk_huge_cells "VERTICES" "$T/hugecells.vtk"
render vtk_point_data_mismatch "POINT_DATA" "$T/pointdata.vtk"
render vtk_bit_type "bit" "$T/bittype.vtk"
render vtk_unknown_section "FROB" "$T/badsection.vtk"
render vtu_huge_count "1000000000000" "$T/hugecount.vtu"
render vtu_not_xml "notxml.vtu" "$T/notxml.vtu"
render raw_odd_size "odd.raw" "$T/odd.raw"
render csv_header_only "headeronly.csv" "$T/headeronly.csv"
render csv_no_z "x, y, z" "$T/noz.csv"
render bgeo_magic "magic.bgeo" "$T/magic.bgeo"
render vdb_magic "magic.vdb" "$T/magic.vdb"
render folder_as_file "folder" "$T/folder.ply"
# a directory without a particle extension was "unknown particle file extension" (issue 53)
render directory_input "is a directory" "$T/folder.ply/.."
expect_bad info_directory "is a directory" info "$T"
expect_bad convert_directory "is a directory" convert "$T" -o "$T/out.ply"
render forced_unknown_format "frob" "$vtk" --format frob

# ---- scenes: duplicate keys, integers that a float would round or overflow
printf '{"particles": "%s", "radius": 0.025, "radius": 0.03}' "$vtk" > "$T/dupkey.json"
printf '{"particles": "%s", "camera": {"width": 64, "width": 32}}' "$vtk" > "$T/dupcam.json"
printf '{"particles": "%s", "methods": {"spheres": {}, "spheres": {}}}' "$vtk" > "$T/dupmethods.json"
printf '{"particles": {"synthetic": "box", "size": [3, 3, 3], "seed": 2147483648}, "radius": 0.025}' > "$T/seedover.json"
printf '{"particles": {"synthetic": "box", "size": [3, 3, 3], "seed": 1.5}, "radius": 0.025}' > "$T/seedfrac.json"
printf '{"particles": {"synthetic": "box", "size": [3, 3, 3], "seed": 1}, "radius": 1e300}' > "$T/radiusover.json"
printf '[1, 2, 3]' > "$T/array.json"
: > "$T/empty.json"
render duplicate_key "appears twice" "$T/dupkey.json"
# bytes that are not UTF-8, in a key, a file name, a command: written \xFF, the rest kept (UTF-8 too)
printf '{"particles": "%s", "ke\377y\303\251": 1}' "$vtk" > "$T/badbyte.json"
render key_not_utf8 'ke\xFFyé' "$T/badbyte.json"
render path_not_utf8 'missing\xFE.vtk' "$T/missing"$'\376'".vtk"
expect_bad command_not_utf8 'frob\xC3' frob$'\303'
render duplicate_camera_key "appears twice" "$T/dupcam.json"
render duplicate_method "appears twice" "$T/dupmethods.json"
render seed_overflow "seed" "$T/seedover.json"
render seed_fraction "seed" "$T/seedfrac.json"
render radius_overflow "radius" "$T/radiusover.json"
render scene_not_object "top level" "$T/array.json"
render empty_scene "empty" "$T/empty.json"

# ---- every subcommand
expect_bad info_folder "folder" info "$T/folder.ply"
expect_bad info_no_file "no particle file" info
expect_bad convert_missing "missing.ply" convert "$T/missing.ply" -o "$T/out.ply"
expect_bad convert_into_missing_dir "nodir" convert "$vtk" -o "$T/nodir/out.ply"
expect_bad diff_missing "missing.exr" diff "$T/missing.exr" "$T/missing.exr"
expect_bad diff_not_image "not an EXR or PNG" diff "$T/nan.csv" "$T/nan.csv"
expect_bad methods_unknown "nosuch" methods nosuch
expect_bad mesh_bad_cube "cube" mesh "$vtk" --set mesh.cube=-1 -o "$T/out.ply"
expect_bad mesh_bad_output "out.stl" mesh "$vtk" -o "$T/out.stl"
expect_bad mesh_set_not_run "reference does not run here (what runs: mesh)" mesh "$vtk" --set reference.step_min=0.5 -o "$T/out.ply"
expect_bad mesh_truncated "truncated.ply" mesh "$T/truncated.ply" -o "$T/out.ply"
expect_bad compare_bad_import "expected NAME=FILE" compare "$vtk" --import frob -o "$T/out"
expect_bad compare_unknown_method "nosuchmethod' (methods: spheres, reference" compare "$vtk" --methods nosuchmethod -o "$T/out"
expect_bad simulate_no_frames "frames" simulate dam_break --frames 0 -o "$T/out_%04d.ply"
expect_bad simulate_bad_pattern "pattern" simulate dam_break --frames 1 -o "$T/out.ply"
expect_bad render_output_is_folder "folder.ply" render "$vtk" -W 16 -H 16 -o "$T/folder.ply"

# ---- backed, but more than the memory available: refused before allocating, exit 1
# (a 2e10-vertex header over a sparse file of 240 GB; a real file under a lowered limit)
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 20000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > "$T/sparse.ply"
truncate -s 240000000200 "$T/sparse.ply"
want_rc=1 expect_bad ply_sparse_2e10 "20000000000 particles need 240.0 GB" info "$T/sparse.ply"
want_rc=1 expect_bad render_sparse_2e10 "sparse.ply" render "$T/sparse.ply" -W 16 -H 16 -o "$T/out.png"
rm -f "$T/sparse.ply"
FLUIDSURF_MEMORY_LIMIT=100K want_rc=1 expect_bad memory_limit "24389 particles need 585.3 kB, but only 102.4 kB" info "$vtk"

# ---- inputs that broke a reader once (tests/fuzz/regress_FORMAT/): refused in one line
for d in "$(dirname "$0")"/fuzz/regress_*/; do
  [ -d "$d" ] || continue
  fmt=$(basename "$d"); fmt=${fmt#regress_}
  for f in "$d"*; do
    [ -f "$f" ] || continue
    case $fmt in
      scene) cp "$f" "$T/regress.json"; render "regress_${fmt}_$(basename "$f")" "regress.json" "$T/regress.json" ;;
      oiio|exr_core) expect_bad "regress_${fmt}_$(basename "$f")" "$(basename "$f")" diff "$f" "$f" ;;
      *) expect_bad "regress_${fmt}_$(basename "$f")" "$(basename "$f")" info "$f" --format "$fmt" ;;
    esac
  done
done

# VTK looped over a forged NumberOfComponents (as INT_MAX) for minutes: refused before it reads
expect_bad vtu_components_forged "NumberOfComponents '4294967295' (at most 1024)" info "$(dirname "$0")/fuzz/regress_vtu/components_4294967295.vtu"
# VTK allocated 4 GB for a forged NumberOfCells, and memset SIZE_MAX bytes for -1e309 (read as -1): refused before it reads
expect_bad vtu_cells_forged "VTU file declares 4294967296 cells, more than its 735 bytes can hold" info "$(dirname "$0")/fuzz/regress_vtu/cells_4294967296.vtu"
expect_bad vtu_cells_negative "bad NumberOfCells in the VTU file" info "$(dirname "$0")/fuzz/regress_vtu/cells_minus_1e309.vtu"

# A failed render must not clobber an existing output.
n=$((n + 1))
echo precious > "$T/keep.png"
"$BIN" render "$T/truncated.vtk" -o "$T/keep.png" 2>/dev/null
if [ "$(cat "$T/keep.png")" != precious ]; then echo "FAIL existing output clobbered"; fails=$((fails + 1)); else echo "ok   existing output kept"; fi
if ls -a "$T" | grep -q '\.tmp'; then echo "FAIL temporary files left: $(ls -a "$T" | grep tmp)"; fails=$((fails + 1)); fi

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
