#!/usr/bin/env bash
# Static obstacles end to end: simulate a scene file with a box and a ball (boundary
# particles, no fluid inside them), render its frame with the same solids through
# compare (the solids drawn, the hidden pixels out of the metrics; diff of its EXRs
# gives the same metrics, through their solid_depth layer), and bad obstacles
# refused with one line naming the file and no output left.
set -u
BIN=$1 T=$2
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
SOLIDS='[{"min": [0.64, 0, 0.16], "max": [0.8, 0.32, 0.48]}, {"centre": [0.4, 0.16, 0.56], "radius": 0.12}]'
echo "{\"box\": [1.2, 0.8, 0.64], \"fluid\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.48, 0.64]}], \"obstacles\": $SOLIDS}" > "$T/sim.json"
echo "{\"box\": [1.2, 0.8, 0.64], \"fluid\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.48, 0.64]}]}" > "$T/sim_plain.json"

"$BIN" simulate "$T/sim.json" --radius 0.04 --frames 3 --fps 30 -q -o "$T/f_%04d.bgeo" --stats "$T/s.csv" 2> "$T/sim.err"
check '[ $? -eq 0 ] && [ -s "$T/f_0003.bgeo" ]' "simulate runs with obstacles"
"$BIN" simulate "$T/sim_plain.json" --radius 0.04 --frames 1 -q --stats "$T/plain.csv" 2> /dev/null
# the stats' provenance line (fs_provenance_line): "# ...; fluid_particles=N; boundary_particles=M; ..."
nb() { head -1 "$1" | sed -n 's/.* boundary_particles=\([0-9]*\);.*/\1/p'; }
nf() { head -1 "$1" | sed -n 's/.* fluid_particles=\([0-9]*\);.*/\1/p'; }
check '[ "$(nb "$T/s.csv")" -gt "$(nb "$T/plain.csv")" ] && [ "$(nf "$T/s.csv")" -lt "$(nf "$T/plain.csv")" ]' \
  "the solids add boundary particles ($(nb "$T/plain.csv") -> $(nb "$T/s.csv")) and take lattice sites from the fluid ($(nf "$T/plain.csv") -> $(nf "$T/s.csv"))"

scene() { # FILE OBSTACLES_JSON_OR_EMPTY
  printf '{"particles": "f_0003.bgeo", "radius": 0.04, "up": "y", %s"camera": {"eye": [1.7, 0.9, 1.6], "target": [0.5, 0.15, 0.3], "width": 128, "height": 128}}\n' \
    "${2:+\"obstacles\": $2, }" > "$1"
}
scene "$T/with.json" "$SOLIDS"
scene "$T/without.json" ""
for s in with without; do
  "$BIN" compare "$T/$s.json" --methods spheres --reference reference -q --no-cache --repeat 1 -o "$T/$s" 2> "$T/$s.err"
  check '[ $? -eq 0 ] && [ -s "$T/$s/metrics.csv" ]' "compare runs ($s obstacles)"
done
both() { awk -F, '!/^#/ && $1 == "spheres" {print $15}' "$1/metrics.csv"; }
check '[ "$(both "$T/with")" -lt "$(both "$T/without")" ]' "hidden pixels leave the metrics ($(both "$T/without") -> $(both "$T/with") px both cover)"
diffpx=$(oiiotool "$T/with/reference.png" "$T/without/reference.png" --absdiff --rangecompress --ch R --printstats 2>/dev/null |
  sed -n 's/.*Max: *\([0-9.]*\).*/\1/p' | head -1)
check 'awk -v d="${diffpx:-0}" "BEGIN {exit !(d > 0.2)}"' "the solids are drawn (largest pixel change ${diffpx:-none})"

# diff agrees with compare: compare's EXRs carry the solids' depth (solid_depth), so
# diff leaves out the same pixels and prints compare's numbers; the same EXRs without
# that layer (as written before it) give the old, unmasked numbers, and no line about solids.
csv_row() { awk -F, '/^method,/ { for (i = 1; i <= NF; i++) h[i] = $i } !/^#/ && $1 == "spheres" { for (i = 5; i <= NF; i++) if (h[i] != "frame_ms") print h[i], $i }' "$1"; }
csv_row "$T/with/metrics.csv" | sort > "$T/compare.txt"
"$BIN" diff "$T/with/spheres.exr" "$T/with/reference.exr" > "$T/diff.out" 2> "$T/diff.err"
check '[ $? -eq 0 ] && grep -q "^solids_masked_px [1-9]" "$T/diff.out"' "diff says it masked the solids: $(grep solids_masked "$T/diff.out")"
grep -v ':\|^solids' "$T/diff.out" | awk '$1 != "n_union"' | sort > "$T/diff.txt"
check '[ -s "$T/compare.txt" ] && cmp -s "$T/compare.txt" "$T/diff.txt"' \
  "diff gives compare's metrics ($(wc -l < "$T/compare.txt") columns; $(diff "$T/compare.txt" "$T/diff.txt" | tr '\n' ' '))"
layers=R,G,B,A,depth,normal.X,normal.Y,normal.Z,thickness,coverage
oiiotool "$T/with/spheres.exr" --ch $layers -o "$T/old_a.exr" && oiiotool "$T/with/reference.exr" --ch $layers -o "$T/old_b.exr"
"$BIN" diff "$T/old_a.exr" "$T/old_b.exr" > "$T/old.out" 2> /dev/null
nb_of() { awk '$1 == "n_both" {print $2}' "$1"; }
psnr_of() { awk '$1 == "psnr_db" {print $2}' "$1"; }
echo "     n_both, psnr_db: compare $(awk '$1 == "n_both" {print $2}' "$T/compare.txt"), $(awk '$1 == "psnr_db" {print $2}' "$T/compare.txt");" \
  "diff now $(nb_of "$T/diff.out"), $(psnr_of "$T/diff.out"); diff of EXRs without solid_depth (old) $(nb_of "$T/old.out"), $(psnr_of "$T/old.out")"
check '[ -n "$(nb_of "$T/old.out")" ] && [ "$(nb_of "$T/old.out")" -gt "$(nb_of "$T/diff.out")" ] && ! grep -q solids "$T/old.out"' \
  "EXRs without the solids' layer read as before: unmasked, no line about solids"
"$BIN" diff "$T/with/spheres.exr" "$T/with/reference.exr" --json > "$T/diff.json"
check 'grep -q "\"solids_masked_px\": $(awk "\$1 == \"solids_masked_px\" {print \$2}" "$T/diff.out")," "$T/diff.json"' "diff --json says the same count"
"$BIN" render "$T/with.json" --method reference -q -o "$T/render.exr" 2> /dev/null
"$BIN" diff "$T/render.exr" "$T/old_b.exr" > "$T/render.out" 2> /dev/null
check '[ "$(awk "\$1 == \"solids_masked_px\" {print \$2}" "$T/render.out")" = "$(awk "\$1 == \"solids_masked_px\" {print \$2}" "$T/diff.out")" ]' \
  "render's EXR carries the solids' layer too (diff masks $(awk '$1 == "solids_masked_px" {print $2}' "$T/render.out") px)"
"$BIN" diff "$T/without/spheres.exr" "$T/without/reference.exr" > "$T/plain.out" 2> /dev/null
check '! grep -q solids "$T/plain.out"' "a scene without solids: no layer, no line"

# a sequence: the temporal measures run with solids in the view
printf '{"particles": {"file": "f_%%04d.bgeo", "first": 1, "last": 3}, "radius": 0.04, "up": "y", "obstacles": %s, "camera": {"eye": [1.7, 0.9, 1.6], "target": [0.5, 0.15, 0.3], "width": 64, "height": 64}}\n' \
  "$SOLIDS" > "$T/seq.json"
"$BIN" compare "$T/seq.json" --methods spheres --reference reference -q --no-cache --repeat 1 -o "$T/seq" 2> "$T/seq.err"
check '[ $? -eq 0 ] && awk -F, "!/^#/ && \$1 == \"spheres\" { n++; for (i = 3; i <= NF; i++) if (\$i == \"nan\" || \$i == \"\") bad++ } END { exit !(n == 1 && !bad) }" "$T/seq/temporal.csv"' \
  "a sequence with solids gives finite temporal measures ($(grep -v '^#' "$T/seq/temporal.csv" 2>/dev/null | tail -1))"

expect_bad() { # NAME CMD... : exit 2, one line naming the file and obstacles[...], no output
  local name=$1; shift
  "$@" > /dev/null 2> "$T/bad.err"
  local rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/bad.err")" -eq 1 ] && grep -q "bad_.*\.json: obstacles\[0\]" "$T/bad.err" && ! ls "$T"/bad_out* > /dev/null 2>&1' \
    "$name: $(cat "$T/bad.err")"
}
echo '{"box": [1, 1, 1], "fluid": [{"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}], "obstacles": [{"centre": [0.7, 0.2, 0.5], "radius": 0}]}' > "$T/bad_sim.json"
expect_bad "simulate refuses a ball of radius 0" "$BIN" simulate "$T/bad_sim.json" --frames 1 -q -o "$T/bad_out_%04d.bgeo"
scene "$T/bad_render.json" '[{"min": [1, 0, 0], "max": [0, 1, 1]}]'
expect_bad "compare refuses a box with min > max" "$BIN" compare "$T/bad_render.json" --methods spheres -q -o "$T/bad_out"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
