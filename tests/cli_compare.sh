#!/usr/bin/env bash
# fluidsurf compare and diff end to end on small scenes: every file with the
# documented columns, sweeps, imports, sequences, diff exit codes, bad arguments.
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
box=$SRC/experiments/scenes/box.json
HEADER='method,variant,reference,frame,mask_iou,depth_bias_r,depth_rmse_r,depth_p95_r,normal_mean_deg,normal_p95_deg,interior_normal_mean_deg,psnr_db,ssim,frame_ms'
size() { iinfo "$1" 2>/dev/null | sed -n 's/.* : *\([0-9]*\) x *\([0-9]*\),.*/\1 \2/p'; }
col() { awk -F, -v c="$1" -v m="$2" -v r="$3" '!/^#/ && $1 == m && $3 == r {print $c; exit}' "$4"; }

# 1. two methods, two references
"$BIN" compare "$box" --methods spheres,reference --reference reference --reference analytic -W 64 -H 64 --repeat 2 -q --no-cache -o "$T/a" 2> "$T/a.err"; rc=$?
check '[ $rc -eq 0 ]' "compare runs"
for f in spheres.png spheres.exr reference.png reference.exr analytic.png diff_spheres.png diff_reference.png metrics.csv timings.csv panel.png report.md; do
  check '[ -s "$T/a/$f" ]' "writes $f"
done
check 'grep -v "^#" "$T/a/metrics.csv" | head -1 | grep -q "^$HEADER"' "metrics.csv columns in order"
check '[ "$(grep -vc "^#" "$T/a/metrics.csv")" -eq 5 ]' "metrics.csv has 2 methods x 2 references"
check 'grep -q "^# .*commit=.*gl_renderer=" "$T/a/metrics.csv"' "metrics.csv provenance line"
check '[ "$(col 5 reference reference "$T/a/metrics.csv")" = 1 ] && [ "$(col 9 reference reference "$T/a/metrics.csv")" = 0 ] && [ "$(col 12 reference reference "$T/a/metrics.csv")" = inf ]' "reference against itself: IoU 1, normal 0, PSNR inf"
check 'awk -F, "!/^#/ && \$1==\"spheres\" && \$3==\"reference\" {exit !(\$9 > 5)}" "$T/a/metrics.csv"' "spheres differ from the reference"
check 'grep -v "^#" "$T/a/timings.csv" | head -1 | grep -qx "method,variant,stage,ms_median,ms_min,ms_max,runs,gpu_ms_median,renderer"' "timings.csv columns"
check 'grep -q "^spheres,,splat,.*,2,[0-9.]*,.*llvmpipe" "$T/a/timings.csv" && grep -q "^reference,,march,.*,2,,CPU" "$T/a/timings.csv"' "timings name stages, runs and renderer"
check 'grep -q "^reference,ground truth,march,.*,1,,CPU$" "$T/a/timings.csv" && grep -q "^analytic,ground truth,analytic,.*,1,,CPU$" "$T/a/timings.csv" && ! grep -q ",cache" "$T/a/timings.csv"' "timings.csv has each reference's first frame as its ground truth rows (--no-cache: rendered)"
read -r pw ph <<< "$(size "$T/a/panel.png")"
check '[ "${pw:-0}" -ge $((2 * 64)) ] && [ "${pw:-0}" -le 600 ] && [ "${ph:-0}" -ge $((2 * 64)) ] && [ "${ph:-0}" -le 300 ]' "panel is 2 columns (ground truth first) x 2 rows of 64 px tiles (${pw}x${ph})"
check 'grep -q "fluidsurf compare" "$T/a/report.md" && grep -q "| spheres |" "$T/a/report.md" && grep -q "fluidsurf:commit" "$T/a/report.md"' "report has the command, the table and the provenance"

# 2. a two-parameter sweep
"$BIN" compare "$box" --methods spheres --set spheres.radius_scale=0.8,1.2 --set spheres.thickness=on,off -W 48 -H 48 --repeat 1 -q --no-cache -o "$T/sweep" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ]' "two-parameter sweep runs"
check '[ "$(grep -vc "^#" "$T/sweep/metrics.csv")" -eq 5 ]' "sweep gives 4 rows"
check 'grep -q "^spheres,radius_scale=1.2;thickness=off,1.2,off,reference," "$T/sweep/metrics.csv"' "variant column p=v;q=w, then a column per swept parameter"
check 'grep -v "^#" "$T/sweep/metrics.csv" | head -1 | grep -q "^method,variant,radius_scale,thickness,reference,frame,mask_iou,"' "metrics.csv has the swept parameters' columns beside variant"
check '[ -s "$T/sweep/spheres_radius_scale-0p8_thickness-on.png" ] && [ -s "$T/sweep/diff_spheres_radius_scale-1p2_thickness-off.png" ]' "variant label in file names (. written p, = written -)"
check '[ -z "$(ls "$T/sweep" | sed "s/\.[a-z]*$//" | grep -vE "^[A-Za-z0-9_-]+$")" ]' "every file name is [A-Za-z0-9_-] plus its extension: $(ls "$T/sweep" | tr '\n' ' ')"
check 'grep -qF "| \`spheres_radius_scale-0p8_thickness-on\` | spheres | radius_scale=0.8;thickness=on | radius_scale=0.8;thickness=on;splat=raster;splat_large_px=0 |" "$T/sweep/report.md"' "report.md maps each label to its method and parameters"
read -r sw sh <<< "$(size "$T/sweep/panel.png")"
check '[ "${sh:-0}" -ge $((2 * 48)) ] && [ "${sh:-0}" -le $((2 * 48 + 150)) ] && [ "${sw:-0}" -ge $((4 * 48)) ]' "sweep panel is a 2-row grid (${sw}x${sh})"

# 2b. the parameter columns across methods: filled only on the rows of the method that sweeps
# them, empty on the others' (the reference has a thickness of its own, which it does not
# sweep: issue 53, the page's sweep grid showed such a row); a reference:P=V label
"$BIN" compare "$box" --methods spheres,reference --set spheres.thickness=on,off --set spheres.radius_scale=0.8,1.2 \
  --reference reference:thickness=off -W 32 -H 32 --repeat 1 -q --no-cache -o "$T/cols" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ] && grep -v "^#" "$T/cols/metrics.csv" | head -1 | grep -q "^method,variant,thickness,radius_scale,reference,frame,"' "parameter columns in --set order"
check 'grep -q "^spheres,thickness=off;radius_scale=0.8,off,0.8,reference:thickness=off,," "$T/cols/metrics.csv" && grep -q "^reference,,,,reference:thickness=off,," "$T/cols/metrics.csv"' "reference's row: no thickness (its own, not swept), no radius_scale"
check '[ -s "$T/cols/reference_thickness-off.exr" ] && grep -qF "| \`reference_thickness-off\` | reference (ground truth) | thickness=off |" "$T/cols/report.md"' "a reference:P=V view is labelled reference_P-V, in report.md's table"

# 3. --import of a written EXR gives zero error against itself
"$BIN" compare "$box" --methods spheres --import mine="$T/a/reference.exr" -W 64 -H 64 --repeat 1 -q --no-cache -o "$T/imp" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ]' "import runs"
check '[ "$(col 5 mine reference "$T/imp/metrics.csv")" = 1 ] && [ "$(col 9 mine reference "$T/imp/metrics.csv")" = 0 ] && [ "$(col 6 mine reference "$T/imp/metrics.csv")" = 0 ]' "imported reference: zero error"

# 4. a sequence: per-frame rows and temporal.csv
printf '{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 2}, "radius": 0.025}' > "$T/seq.json"
"$BIN" compare "$T/seq.json" --methods spheres -W 40 -H 40 --repeat 1 -q --no-cache -o "$T/seq" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ]' "sequence runs"
check '[ "$(grep -vc "^#" "$T/seq/metrics.csv")" -eq 4 ] && grep -q "^spheres,,reference,2," "$T/seq/metrics.csv"' "per-frame rows"
check 'grep -v "^#" "$T/seq/temporal.csv" | head -1 | grep -qx "method,variant,frames,normal_change_deg,reference_normal_change_deg,normal_temporal_error_deg,depth_temporal_error_r" && grep -q "^spheres,,3,[0-9.]*,[0-9.]*,[0-9.]*,[0-9.]*$" "$T/seq/temporal.csv"' "temporal.csv with the reference's own change and the error against it"

# 4a. frames stream: a sequence past the old cap of 256 frames runs, one row a frame
printf '{"particles": {"synthetic": "slab", "size": [4, 2, 4], "first": 0, "last": 299}, "radius": 0.025}' > "$T/long.json"
"$BIN" compare "$T/long.json" --methods spheres --reference analytic -W 8 -H 8 --repeat 1 -q --no-cache -o "$T/long" 2> "$T/long.err"; rc=$?
check '[ $rc -eq 0 ] && [ "$(grep -vc "^#" "$T/long/metrics.csv")" -eq 301 ] && grep -q "^spheres,,analytic,299," "$T/long/metrics.csv" && [ -s "$T/long/spheres_f0299.exr" ]' \
  "300 frames (past the old cap of 256) stream through compare: $(head -c 200 "$T/long.err")"

# 4b. temporal error where the answer is known: a static slab re-jittered every frame.
# Against analytic (its change is exactly 0) a method's error is its own change (the
# pixel sets differ by the few the analytic slab does not cover: 0.5% slack); against
# reference, which moves with the jitter, it is not.
printf '{"particles": {"synthetic": "slab", "size": [16, 4, 16], "jitter": 0.1, "first": 0, "last": 3}, "radius": 0.025}' > "$T/jit.json"
"$BIN" compare "$T/jit.json" --methods spheres,raycast_pca --reference analytic --reference reference -W 64 -H 64 --repeat 1 -q --no-cache -o "$T/jit" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ]' "jittered slab sequence runs"
tcol() { grep "^$1," "$T/$2/temporal.csv" | cut -d, -f"$3"; }
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0 && d <= 0.005 * a + 1e-4) }'; }
check '[ "$(tcol spheres jit 5)" = 0.0000 ] && close "$(tcol spheres jit 6)" "$(tcol spheres jit 4)" && close "$(tcol raycast_pca jit 6)" "$(tcol raycast_pca jit 4)"' \
  "against a static reference the temporal error equals the change ($(tcol raycast_pca jit 4-7))"
"$BIN" compare "$T/jit.json" --methods raycast_pca --reference reference -W 64 -H 64 --repeat 1 -q --no-cache -o "$T/jit2" 2>/dev/null
check 'awk -v c="$(tcol raycast_pca jit2 4)" -v r="$(tcol raycast_pca jit2 5)" -v e="$(tcol raycast_pca jit2 6)" "BEGIN { exit !(r > 1 && (e - c > 0.2 || c - e > 0.2)) }"' \
  "against the moving reference it differs from the change ($(tcol raycast_pca jit2 4-7))"
check '[ -s "$T/seq/spheres_f0002.png" ]' "per-frame images"

# 5. diff exit codes
"$BIN" diff "$T/a/reference.exr" "$T/a/reference.exr" --fail-iou 0.99 --fail-normal-deg 0.1 --fail-depth-r 0.01 > "$T/d1" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "^mask_iou 1$" "$T/d1"' "diff of equal outputs exits 0"
"$BIN" diff "$T/a/spheres.exr" "$T/a/reference.exr" --fail-normal-deg 5 > "$T/d2" 2>&1; rc=$?
check '[ $rc -eq 3 ] && grep -q "^FAIL normal" "$T/d2"' "diff beyond a threshold exits 3"
"$BIN" diff "$T/a/spheres.exr" "$T/a/reference.exr" > "$T/d3" 2>&1; rc=$?
check '[ $rc -eq 0 ]' "diff without thresholds exits 0"

# 5b. an output folder that holds another run's outputs (common/study_dir/outputs_list.h)
snap() { (cd "$1" && find . -type f -printf '%p %s %T@\n' | sort); }
before=$(snap "$T/a")
"$BIN" compare "$box" --methods spheres -W 32 -H 32 --repeat 1 -q --no-cache -o "$T/a" 2> "$T/used.err"; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/used.err")" -eq 1 ] && grep -q "^fluidsurf: $T/a: holds another run.s outputs .*--force.*--resume" "$T/used.err" && [ "$(snap "$T/a")" = "$before" ]' \
  "a second compare into a used folder is refused, nothing changed: $(cat "$T/used.err")"
mkdir -p "$T/reuse" && echo keep > "$T/reuse/notes.txt" && cp "$T/a/spheres.png" "$T/reuse/mine.png"
"$BIN" compare "$box" --methods spheres,reference --set spheres.radius_scale=0.8,1.2 -W 32 -H 32 --repeat 1 -q --no-cache -o "$T/reuse" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ] && [ -s "$T/reuse/spheres_radius_scale-0p8.png" ] && grep -qx "metrics.csv" "$T/reuse/fluidsurf-outputs.txt"' "a folder with only other files is fine; compare lists what it wrote in fluidsurf-outputs.txt"
"$BIN" compare "$box" --methods spheres -W 32 -H 32 --repeat 1 --no-cache --force -o "$T/reuse" 2> "$T/force.err"; rc=$?
check '[ $rc -eq 0 ] && [ ! -e "$T/reuse/spheres_radius_scale-0p8.png" ] && [ ! -e "$T/reuse/diff_reference.png" ] && [ -s "$T/reuse/spheres.png" ] && [ "$(cat "$T/reuse/notes.txt")" = keep ] && [ -s "$T/reuse/mine.png" ] && grep -q "note: $T/reuse: --force: removed" "$T/force.err"' \
  "--force removes the earlier run's files only: $(ls "$T/reuse" | tr '\n' ' ')"
"$BIN" compare "$box" --methods spheres -W 32 -H 32 --repeat 1 --no-cache --resume -o "$T/reuse" 2> "$T/resume.err"; rc=$?
check '[ $rc -eq 0 ] && grep -q "resume: 1 work item(s) loaded" "$T/resume.err"' "--resume into a used folder keeps what matches"
before=$(snap "$T/reuse")
"$BIN" compare "$box" --methods reference -W 32 -H 32 --repeat 1 -q --no-cache --resume -o "$T/reuse" 2> "$T/other.err"; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/other.err")" -eq 1 ] && grep -q "^fluidsurf: $T/reuse: --resume: the earlier run there has views this one does not make (spheres.exr).*--force" "$T/other.err" && [ "$(snap "$T/reuse")" = "$before" ]' \
  "--resume with another method list is refused, nothing changed: $(cat "$T/other.err")"
rm "$T/reuse/fluidsurf-outputs.txt" # as an older fluidsurf left it
"$BIN" compare "$box" --methods spheres -W 32 -H 32 --repeat 1 -q --no-cache -o "$T/reuse" 2> "$T/old.err"; rc=$?
check '[ $rc -eq 2 ] && grep -q "holds another run.s outputs (metrics.csv" "$T/old.err"' "a folder an older fluidsurf wrote (no list) is recognised by its files"
"$BIN" compare "$box" --methods reference -W 32 -H 32 --repeat 1 -q --no-cache --force -o "$T/reuse" 2>/dev/null; rc=$?
check '[ $rc -eq 0 ] && [ ! -e "$T/reuse/spheres.png" ] && [ ! -e "$T/reuse/diff_spheres.png" ] && [ -s "$T/reuse/mine.png" ] && [ -s "$T/reuse/notes.txt" ]' \
  "--force there removes its EXRs and the PNGs named after them, no other file: $(ls "$T/reuse" | tr '\n' ' ')"

# 6. bad arguments: exit 2, one line, no output folder made
bad() {
  local name=$1 word=$2; shift 2
  rm -rf "$T/bad"
  "$BIN" "$@" > /dev/null 2> "$T/bad.err"
  local rc=$?
  check "[ $rc -eq 2 ] && [ \$(wc -l < '$T/bad.err') -eq 1 ] && grep -q '^fluidsurf: ' '$T/bad.err' && grep -qF -- '$word' '$T/bad.err'" "$name: $(cat "$T/bad.err")"
}
oiiotool --create 16x16 3 -o "$T/rgb_only.exr" 2>/dev/null
bad "unknown method" nosuch compare "$box" --methods spheres,nosuch -o "$T/bad"
bad "unknown parameter" nope compare "$box" --methods spheres --set spheres.nope=1,2 -o "$T/bad"
bad "bad value" radius_scale compare "$box" --methods spheres --set spheres.radius_scale=0.5,abc -o "$T/bad"
bad "bad reference" "--reference" compare "$box" --methods spheres --reference bogus -o "$T/bad"
bad "analytic needs synthetic" analytic compare "$SRC/experiments/scenes/dam_break.json" --methods spheres --reference analytic -o "$T/bad"
bad "EXR without the channels" "no channel" compare "$box" --methods spheres --import x="$T/rgb_only.exr" -o "$T/bad"
bad "import of the wrong size" "64x64" compare "$box" --methods spheres -W 32 -H 32 --import x="$T/a/reference.exr" -o "$T/bad"
bad "--resume with --force" "choose one" compare "$box" --methods spheres --resume --force -o "$T/bad"
bad "a value swept twice" "file label spheres_radius_scale-0p8" compare "$box" --methods spheres --set spheres.radius_scale=0.8,0.8 -o "$T/bad"
bad "an import NAME a file name cannot hold" "letters, digits" compare "$box" --methods spheres --import "a.b=$T/a/reference.exr" -o "$T/bad"
bad "unwritable output folder" "$T/a/metrics.csv" compare "$box" --methods spheres -o "$T/a/metrics.csv/sub"
bad "diff of a non-fluidsurf EXR" "no channel" diff "$T/rgb_only.exr" "$T/a/reference.exr"
bad "diff of one file" "two EXR" diff "$T/a/reference.exr"
check '[ ! -e "$T/bad" ]' "no output folder left by bad input"

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
