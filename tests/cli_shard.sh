#!/usr/bin/env bash
# compare --shard K/N and fluidsurf merge (docs/DESIGN.md, "Sharded studies"):
# shards run side by side with xargs -P (the README's recipe) and merged equal one
# process's output, timings and provenance aside; a killed shard is finished with
# --resume; shards of another study, missing or unfinished shards and unusable
# outputs each exit 2 with one line and leave nothing behind.
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
cd "$T" || exit 1
# Five frames of a moving slab, two methods, two references: 2 x 5 reference items
# and 2 x 5 method items, so each shard holds a mix and consecutive frames split.
printf '{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 4, "moving": true}, "radius": 0.025}' > seq.json
ARGS=(seq.json --methods spheres,aniso_ssf --reference reference --reference analytic -W 48 -H 48 --repeat 1 -q --no-cache --counters)
"$BIN" compare "${ARGS[@]}" -o single 2> single.err
check '[ -s single/metrics.csv ] && [ -s single/temporal.csv ] && [ -s single/counters.csv ]' "single-process run writes metrics, temporal and counters"

# 1. the recipe of README.md: N shards at once on one machine, then merge
mkdir -p study/shards
seq 1 3 | xargs -P 3 -I{} "$BIN" compare "${ARGS[@]}" --shard {}/3 -o study/shards/{} 2> xargs.err; rc=$?
check '[ $rc -eq 0 ] && [ -f study/shards/1/DONE ] && [ -f study/shards/2/DONE ] && [ -f study/shards/3/DONE ]' "three shards run with xargs -P 3, each ends with DONE"
check 'grep -q "^shard	2	3$" study/shards/2/shard.txt && [ -f study/shards/2/DONE ] && [ ! -e study/shards/2/metrics.csv ]' "a shard holds its manifest and items, no study outputs"
exr=$(ls study/shards/2/*.exr | head -1)
check 'iinfo -v "$exr" | grep -q "fluidsurf:shard: \"2/3\""' "a shard's EXR provenance names the shard"
# each shard renders a share: no shard holds every item, every shard holds one
check 'for k in 1 2 3; do c=$(grep -c "^entry	" study/shards/$k/shard.txt); [ "$c" -ge 1 ] && [ "$c" -lt 10 ] || exit 1; done' "every shard renders some but not all of the 10 method items"
# consecutive frames of one method in different shards (temporal.csv must join them)
split=$(for k in 1 2 3; do awk -F'\t' -v k=$k '$1 == "entry" && $3 == "spheres" {print $4, k}' study/shards/$k/shard.txt; done | sort -n |
        awk '{o[$1] = $2} END {for (f = 0; f < 4; f++) if (o[f] != o[f + 1]) s++; print s + 0}')
check '[ "$split" -ge 1 ]' "spheres' consecutive frames sit in different shards ($split of 4 pairs)"
"$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o study/merged 2> merge.err; rc=$?
check '[ $rc -eq 0 ] && [ ! -s merge.err ] || [ $rc -eq 0 ]' "merge runs"
body() { grep -v '^#' "$1"; }
# metrics.csv: column 14 is frame_ms, the only timing column
check 'diff <(body single/metrics.csv | cut -d, -f1-13,15-) <(body study/merged/metrics.csv | cut -d, -f1-13,15-) >/dev/null' "merged metrics.csv equals the single process's, frame_ms aside"
check 'diff <(body single/temporal.csv) <(body study/merged/temporal.csv) >/dev/null' "merged temporal.csv equals the single process's"
check 'diff <(body single/counters.csv) <(body study/merged/counters.csv) >/dev/null' "merged counters.csv equals the single process's"
check 'diff <(body single/timings.csv | cut -d, -f1-3,7,9) <(body study/merged/timings.csv | cut -d, -f1-3,7,9) >/dev/null' "merged timings.csv has the same rows, runs and renderers"
check 'grep -q "shards=3;" study/merged/metrics.csv && ! grep -q "shards=" single/metrics.csv' "merged provenance says shards=3"
same=1
for f in single/*.png; do
  b=${f#single/}
  [ "$b" = panel.png ] && continue  # its captions hold frame times
  cmp -s "$f" "study/merged/$b" || { same=0; echo "  differs: $b"; }
done
check '[ $same -eq 1 ] && [ "$(ls single/*.png | wc -l)" -eq "$(ls study/merged/*.png | wc -l)" ]' "every PNG but the panel is byte-identical, none missing or extra"
same=1
for f in single/*.exr; do  # pixels equal; the header's time, frame_ms and shard differ
  idiff "$f" "study/merged/${f#single/}" >/dev/null 2>&1 || { same=0; echo "  differs: ${f#single/}"; }
done
check '[ $same -eq 1 ] && [ "$(ls single/*.exr | wc -l)" -eq "$(ls study/merged/*.exr | wc -l)" ]' "every EXR has the single run's pixels"
size() { iinfo "$1" 2>/dev/null | sed -n 's/.* : *\([0-9]*\) x *\([0-9]*\),.*/\1 \2/p'; }
read -r sw sh <<< "$(size single/panel.png)"; read -r mw mh <<< "$(size study/merged/panel.png)"
# the captions hold the frame times, so the width follows their digits
check '[ -n "$sh" ] && [ "$sh" = "$mh" ] && [ $((mw - sw)) -le 24 ] && [ $((sw - mw)) -le 24 ]' "the merged panel has the single panel's layout (${mw}x${mh} against ${sw}x${sh})"
check 'grep -q "fluidsurf:shards.*3" study/merged/report.md && grep -q "| aniso_ssf |" study/merged/report.md && ! grep -q -- "--shard" study/merged/report.md' "merged report.md has the table, names the shards, shows the command without --shard"
check '[ -z "$(ls -d study/merged.merging-* 2>/dev/null)" ]' "no staging folder left after a merge"
# a second merge into the merged folder: refused unless --force, which keeps other files
echo keep > study/merged/notes.txt
"$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o study/merged 2> again.err; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < again.err)" -eq 1 ] && grep -q "holds another run.s outputs" again.err' "merge into a used folder is refused ($(cat again.err))"
"$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o study/merged --force 2>/dev/null; rc=$?
check '[ $rc -eq 0 ] && [ -s study/merged/notes.txt ] && diff <(body single/metrics.csv | cut -d, -f1-13,15-) <(body study/merged/metrics.csv | cut -d, -f1-13,15-) >/dev/null' "merge --force replaces it, the other file kept"

# 2. a shard killed midway: no DONE, merge names it; --resume finishes it
rm study/shards/2/DONE study/shards/2/spheres_f0001.exr 2>/dev/null
"$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o study/m2 2> m2.err; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < m2.err)" -eq 1 ] && grep -q "study/shards/2.*DONE\|DONE.*study/shards/2" m2.err && [ ! -e study/m2 ]' "a shard without DONE: exit 2, one line naming it, nothing written ($(cat m2.err))"
"$BIN" compare "${ARGS[@]}" --shard 2/3 --resume -o study/shards/2 2> resume.err; rc=$?
check '[ $rc -eq 0 ] && [ -f study/shards/2/DONE ]' "--resume finishes the shard"
"$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o study/m2 2>/dev/null; rc=$?
check '[ $rc -eq 0 ] && diff <(body single/metrics.csv | cut -d, -f1-13,15-) <(body study/m2/metrics.csv | cut -d, -f1-13,15-) >/dev/null' "the resumed study merges to the same metrics"

# 3. bad input: one line, exit 2, nothing written
bad() { # label, expected words, command...
  local label=$1 words=$2; shift 2
  "$@" > bad.out 2> bad.err; local rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < bad.err)" -eq 1 ] && grep -qi "$words" bad.err' "$label: exit 2, one line ($(head -c 150 bad.err))"
}
for s in 0/4 5/4 x/y 3 1/0 1/2000; do
  bad "--shard $s" "shard" "$BIN" compare "${ARGS[@]}" --shard "$s" -o "bad_$s"
  check '[ ! -e "bad_$s" ]' "--shard $s leaves no output folder"
done
mkdir -p other
"$BIN" compare seq.json --methods spheres --reference reference -W 48 -H 48 --repeat 1 -q --no-cache --counters --shard 3/3 -o other/3 2>/dev/null
bad "a shard of another study (other methods)" "another compare command" "$BIN" merge study/shards/1 study/shards/2 other/3 -o m4
# the same command after the scene file changed: only the scene hash tells
cp seq.json seq.keep
printf '{"particles": {"synthetic": "slab", "size": [12, 4, 10], "first": 0, "last": 4, "moving": true}, "radius": 0.025}' > seq.json
"$BIN" compare "${ARGS[@]}" --shard 3/3 -o other/s3 2>/dev/null
mv seq.keep seq.json
bad "a shard of another scene (same command)" "scene hash" "$BIN" merge study/shards/1 study/shards/2 other/s3 -o m4
"$BIN" compare "${ARGS[@]}" --shard 1/4 -o other/n4 2>/dev/null
bad "a shard of another shard count" "shard count\|of 4\|4 shards\|/4" "$BIN" merge other/n4 study/shards/2 study/shards/3 -o m4
bad "a missing shard" "shard 3 of 3 is missing" "$BIN" merge study/shards/1 study/shards/2 -o m4
bad "the same shard twice" "twice\|duplicate\|both" "$BIN" merge study/shards/1 study/shards/2 study/shards/2 -o m4
bad "a folder that is no shard" "shard" "$BIN" merge single study/shards/2 study/shards/3 -o m4
check '[ ! -e m4 ] && [ -z "$(ls -d m4.merging-* 2>/dev/null)" ]' "refused merges leave no output and no staging folder"
bad "an output under a missing folder" "cannot create" "$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o nonexist/m5
bad "an output that is a file" "not a folder" "$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o seq.json
bad "an output that is a shard's folder" "shard 2's folder" "$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o study/shards/2
if [ "$(id -u)" -ne 0 ]; then
  mkdir -p ro && chmod 555 ro
  bad "an unwritable output folder" "not writable" "$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o ro
  chmod 755 ro
else
  bad "an output on a read-only file system" "cannot create" "$BIN" merge study/shards/1 study/shards/2 study/shards/3 -o /proc/m5
fi
check 'cmp -s <(body study/merged/metrics.csv) <(body study/merged/metrics.csv) && [ -f study/shards/2/DONE ]' "refused merges touched no shard"

echo "$((n - fails))/$n passed"
[ $fails -eq 0 ]
