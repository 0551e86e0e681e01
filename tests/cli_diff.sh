#!/usr/bin/env bash
# fluidsurf diff: the metrics as text and as JSON, -o heatmaps, EXRs that cannot be
# compared refused in one line (another size or camera: exit 2), another scene or r
# a warning (--strict: refused), and EXRs whose empty depth OpenImageIO's idiff and
# oiiotool --stats read as finite numbers.
set -u
BIN=$1 T=$2
rm -rf "$T"; mkdir -p "$T"; cd "$T" || exit 1
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
# scene FILE EYE_X SEED: a synthetic box at 48x48 seen from a fixed camera
scene() {
  printf '{"particles": {"synthetic": "box", "jitter": 0.1, "seed": %s}, "radius": 0.025,
 "camera": {"eye": [%s, 1.1, 0.8], "target": [0.06, 0.3, -0.015], "fov": 40, "width": 48, "height": 48}}\n' "$3" "$2" > "$1"
}
scene a.json 1.5 1; scene eye.json 1.8 1; scene seed.json 1.5 2
render() { "$BIN" render "$1" --method "$2" -q -o "$3" "${@:4}" 2>> render.err || echo "render $* failed" >> render.err; }
render a.json reference ref.exr
render a.json spheres sph.exr
render a.json spheres small.exr -W 32 -H 32
render eye.json spheres eye.exr
render a.json spheres r.exr --radius 0.03
render seed.json spheres seed.exr
check '[ ! -s render.err ]' "the renders ($(head -c 300 render.err))"
oiiotool sph.exr --eraseattrib "fluidsurf:.*" -o bare.exr 2> /dev/null
# d NAME ARGS...: runs diff, stdout to NAME.out, stderr to NAME.err, exit status to NAME.rc
d() { local name=$1; shift; "$BIN" diff "$@" > "$name.out" 2> "$name.err"; echo $? > "$name.rc"; }
rc() { cat "$1.rc"; }
lines() { wc -l < "$1.err"; }
val() { awk -v k="$2" '$1 == k {print $2}' "$1.out"; }

# 1. comparable files: every metric, no warning
d same sph.exr ref.exr
names="mask_iou depth_bias_r depth_rmse_r depth_p95_r normal_mean_deg normal_p95_deg interior_normal_mean_deg psnr_db ssim n_both n_interior depth_median_r depth_abs_p50_r depth_abs_p95_r depth_abs_p99_r depth_over_1r_frac n_union"
missing=$(for k in $names; do [ -n "$(val same "$k")" ] || echo "$k"; done)
check '[ "$(rc same)" = 0 ] && [ ! -s same.err ] && [ -z "$missing" ]' "spheres against the reference: every metric, no warning (missing: $missing; $(head -c 300 same.err))"
check 'awk -v a="$(val same depth_abs_p50_r)" -v b="$(val same depth_abs_p99_r)" -v f="$(val same depth_over_1r_frac)" "BEGIN { exit !(a >= 0 && b >= a && f >= 0 && f <= 1) }"' \
  "the new depth metrics are ordered and a share ($(val same depth_abs_p50_r), $(val same depth_abs_p99_r), $(val same depth_over_1r_frac))"

# 2. --json: one object that strict JSON parsers read, the same numbers as the text
d json sph.exr ref.exr --json
d json_fail sph.exr ref.exr --json --fail-normal-deg 0.001
d json_equal ref.exr ref.exr --json
json_ok() {
  python3 - "$@" <<'EOF'
import json, math, sys
def no_const(c): raise ValueError("not strict JSON: " + c)
j = json.load(open(sys.argv[1] + ".out"), parse_constant=no_const)
text = dict(l.split(None, 1) for l in open(sys.argv[2] + ".out") if not l.startswith(("a:", "b:", "r:", "FAIL")))
for k, v in text.items():
    got = j[k]
    assert abs(got - float(v)) <= 1e-5 * max(1, abs(got)), (k, got, v)
assert j["a"] == "sph.exr" and j["b"] == "ref.exr" and abs(j["r"] - 0.025) < 1e-7, j
EOF
}
# jtrue NAME EXPR: EXPR holds of j, NAME.out read as strict JSON (no NaN or Infinity tokens)
jtrue() {
  python3 -c "import json, math, sys
def no_const(c): raise ValueError('not strict JSON: ' + c)
j = json.load(open(sys.argv[1] + '.out'), parse_constant=no_const)
assert $2, j" "$1" 2>> json.py.err
}
check '[ "$(rc json)" = 0 ] && json_ok json same 2>> json.py.err && jtrue json "j[\"failed\"] == []"' \
  "--json parses as strict JSON with the text's numbers ($(head -c 300 json.py.err))"
check '[ "$(rc json_fail)" = 3 ] && jtrue json_fail "j[\"failed\"] == [\"normal_mean_deg > 0.001\"]"' \
  "--json with a crossed threshold: exit 3 and the threshold in \"failed\" ($(rc json_fail))"
check '[ "$(rc json_equal)" = 0 ] && jtrue json_equal "math.isinf(j[\"psnr_db\"]) and j[\"mask_iou\"] == 1"' \
  "--json of equal files: PSNR infinity as 1e999, IoU 1"

# 3. -o FILE.png: compare's heatmaps
d png sph.exr ref.exr -o heat.png
check '[ "$(rc png)" = 0 ] && [ "$(iinfo heat.png 2> /dev/null | sed -n "s/.* : *\([0-9]*\) x .*png.*/\1/p")" -gt 96 ]' \
  "-o heat.png writes a PNG wider than the two 48 px heatmaps ($(iinfo heat.png 2>&1 | head -1))"
d png_bad sph.exr ref.exr -o heat.exr
check '[ "$(rc png_bad)" = 2 ] && [ "$(lines png_bad)" = 1 ] && grep -q "heat.exr" png_bad.err && [ ! -e heat.exr ]' "-o heat.exr is refused ($(cat png_bad.err))"

# 4. apples and oranges: another size or camera is refused, one line naming both files
d size sph.exr small.exr
check '[ "$(rc size)" = 2 ] && [ "$(lines size)" = 1 ] && [ ! -s size.out ] && grep "sph.exr" size.err | grep "small.exr" | grep "48x48" | grep -q "32x32"' \
  "another size: exit 2, one line ($(cat size.err))"
d camera sph.exr eye.exr
check '[ "$(rc camera)" = 2 ] && [ "$(lines camera)" = 1 ] && [ ! -s camera.out ] && grep "sph.exr" camera.err | grep "eye.exr" | grep "camera" | grep -q "eye 1.5"' \
  "another camera: exit 2, one line ($(cat camera.err))"

# 5. another r or scene: a warning, refused under --strict
d r sph.exr r.exr
check '[ "$(rc r)" = 0 ] && [ "$(lines r)" = 1 ] && grep "^fluidsurf: warning: " r.err | grep "r = 0.025" | grep -q "r = 0.03" && [ "$(val r mask_iou)" != "" ]' \
  "another r: a warning, the metrics ($(cat r.err))"
d r_strict sph.exr r.exr --strict
check '[ "$(rc r_strict)" = 2 ] && [ "$(lines r_strict)" = 1 ] && [ ! -s r_strict.out ] && grep "r = 0.03" r_strict.err | grep -q -- "--strict"' \
  "another r under --strict: exit 2, one line ($(cat r_strict.err))"
d scene sph.exr seed.exr
check '[ "$(rc scene)" = 0 ] && [ "$(lines scene)" = 1 ] && grep "^fluidsurf: warning: " scene.err | grep -q "different scenes"' \
  "another scene: a warning ($(cat scene.err))"
d scene_strict sph.exr seed.exr --strict
check '[ "$(rc scene_strict)" = 2 ] && [ "$(lines scene_strict)" = 1 ] && grep "different scenes" scene_strict.err | grep -q -- "--strict"' \
  "another scene under --strict: exit 2, one line ($(cat scene_strict.err))"
d bare bare.exr ref.exr
check '[ "$(rc bare)" = 0 ] && [ "$(lines bare)" = 3 ] && [ "$(grep -c "^fluidsurf: warning: bare.exr has no fluidsurf:" bare.err)" = 3 ]' \
  "an EXR without provenance: three warnings, camera, scene and r unchecked ($(tr '\n' '|' < bare.err))"
d bare_strict bare.exr ref.exr --strict
check '[ "$(rc bare_strict)" = 2 ] && [ "$(lines bare_strict)" = 1 ]' "an EXR without provenance under --strict: refused ($(cat bare_strict.err))"

# 6. OpenImageIO's tools read finite numbers: empty depth is 0 (fluidsurf:empty_depth)
idiff sph.exr ref.exr > idiff.txt 2>&1
mean=$(sed -n 's/^ *Mean error = //p' idiff.txt)
check 'awk -v m="$mean" "BEGIN { exit !(m != \"\" && m + 0 == m && m !~ /inf|nan/) }"' "idiff's mean error is finite ($mean)"
check 'oiiotool --stats ref.exr 2>&1 | grep -q "InfCount: 0 0 0 0 0 0 0 0 0 0" && oiiotool --stats ref.exr 2>&1 | grep -q "NanCount: 0 0 0 0 0 0 0 0 0 0"' \
  "oiiotool --stats: no inf or NaN in any channel"
check 'iinfo -v ref.exr | grep -q "fluidsurf:empty_depth: \"0\""' "the EXR says how empty depth is marked"

# 7. every gate (issue 53: only IoU, normal and depth had one): each passes where the metric
# meets it and exits 3 naming itself (text and --json) where it does not
gate() { # NAME OPTION PASSING FAILING FAILTEXT
  local name=$1 opt=$2 pass=$3 bad=$4 text=$5 ok=0
  d "g_$name" sph.exr ref.exr "$opt" "$pass"
  d "gf_$name" sph.exr ref.exr "$opt" "$bad"
  d "gj_$name" sph.exr ref.exr "$opt" "$bad" --json
  [ "$(rc "g_$name")" = 0 ] && [ "$(rc "gf_$name")" = 3 ] && grep -qxF "FAIL $text" "gf_$name.out" &&
    [ "$(rc "gj_$name")" = 3 ] && jtrue "gj_$name" "j['failed'] == ['$text']" && ok=1
  check '[ $ok = 1 ]' "$opt $pass passes, $opt $bad exits 3 with 'FAIL $text' in text and JSON ($name = $(val same "$name"))"
}
gate ssim --fail-ssim 0.1 1 "ssim < 1"
gate psnr_db --fail-psnr 1 1000 "psnr_db < 1000"
gate interior_normal_mean_deg --fail-interior-normal-deg 90 0.001 "interior_normal_mean_deg > 0.001"
gate depth_abs_p95_r --fail-depth-p95-r 1000 0 "depth_abs_p95_r > 0"
d gates_all sph.exr ref.exr --json --fail-ssim 1 --fail-psnr 1000 --fail-interior-normal-deg 0.001 --fail-depth-p95-r 0
check '[ "$(rc gates_all)" = 3 ] && jtrue gates_all "len(j[\"failed\"]) == 4"' "the four gates together: four in \"failed\""
d gates_equal ref.exr ref.exr --fail-ssim 1 --fail-psnr 1000 --fail-interior-normal-deg 0 --fail-depth-p95-r 0
check '[ "$(rc gates_equal)" = 0 ]' "equal files pass the strictest gates (PSNR infinite, SSIM 1, errors 0)"
d gate_bad sph.exr ref.exr --fail-ssim 2
check '[ "$(rc gate_bad)" = 2 ] && [ "$(lines gate_bad)" = 1 ] && grep -q -- "--fail-ssim" gate_bad.err' "--fail-ssim 2 is refused ($(cat gate_bad.err))"

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
