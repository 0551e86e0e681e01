#!/usr/bin/env bash
# The reference cache of compare and render (docs/DESIGN.md, "Reference cache"),
# end to end with real EXR entries at 128x128: a miss then a hit with identical
# metrics and images; a changed parameter, camera or particle set misses; a
# truncated or byte-flipped entry is rendered again with one warning; an
# unusable folder warns and the run goes on; --no-cache and render without
# --cache leave the default folder untouched.
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
export XDG_CACHE_HOME=$T/xdg   # the default folder, $XDG_CACHE_HOME/fluidsurf, inside the test's own
C=$T/xdg/fluidsurf
box=$SRC/experiments/scenes/box.json
# cmpr NAME [ARGS]: compare into $T/NAME with the default cache
cmpr() { local d=$1; shift; "$BIN" compare "$box" --methods spheres -W 128 -H 128 --repeat 1 -q -o "$T/$d" "$@" 2> "$T/$d.err"; }
# metrics without frame_ms (the methods' timings differ run to run)
metrics() { grep -v '^#' "$T/$1/metrics.csv" | cut -d, -f1-13,15-; }
# ref_stage DIR STAGE: the ground truth row of that stage in timings.csv
ref_stage() { grep -q "^reference[^,]*,ground truth,$2," "$T/$1/timings.csv"; }
entries() { find "$C" -name 'gbuffer-*.exr' 2>/dev/null | wc -l; }
same_images() { cmp -s "$T/$1/reference.png" "$T/$2/reference.png" && idiff -q "$T/$1/reference.exr" "$T/$2/reference.exr" > /dev/null 2>&1; }

# 1. a miss stores an entry; the same run again loads it
cmpr miss; rc=$?
check '[ $rc -eq 0 ] && [ ! -s "$T/miss.err" ] && [ "$(entries)" -eq 1 ]' "a miss stores one entry in \$XDG_CACHE_HOME/fluidsurf"
check 'ref_stage miss march && ref_stage miss cache_store && ! ref_stage miss cache' "a miss times march and cache_store, no cache stage"
check 'grep -q "rendered, stored as \`$C/gbuffer-[0-9a-f]*\.exr\`" "$T/miss/report.md"' "report.md names the stored entry"
entry=$(find "$C" -name 'gbuffer-*.exr' | head -1)
check 'iinfo -v "$entry" 2>/dev/null | grep -q "fluidsurf:cache_key" && iinfo -v "$entry" | grep -q "channel list: R, G, B, A, depth"' "the entry is a G-buffer EXR with its key attribute"
cmpr hit; rc=$?
check '[ $rc -eq 0 ] && grep -qF "from the cache: \`$entry\`" "$T/hit/report.md"' "a hit is named in report.md with its entry file"
check 'ref_stage hit cache && ! ref_stage hit march && ! ref_stage hit cache_store' "a hit times the stage cache in place of march"
check '[ "$(metrics miss)" = "$(metrics hit)" ] && [ -n "$(metrics hit)" ]' "metrics with a hit are identical"
check 'same_images miss hit' "reference.png and reference.exr with a hit are identical"
check 'iinfo -v "$T/hit/reference.exr" | grep -q "fluidsurf:params: \"step_min=" && [ "$(iinfo -v "$T/miss/reference.exr" | sed 1d | grep -v DateTime)" = "$(iinfo -v "$T/hit/reference.exr" | sed 1d | grep -v DateTime)" ]' "reference.exr with a hit has the same header and provenance"

# 2. what the key holds: a parameter, the camera, the particles
n0=$(entries)
cmpr param --reference reference:step_min=0.03
check 'ref_stage param march && [ "$(entries)" -eq $((n0 + 1)) ]' "a changed reference parameter misses"
sed 's/"width": 256, "height": 256/"width": 256, "height": 256, "fov": 35/' "$box" > "$T/fov.json"
sed 's/"seed": 1/"seed": 2/' "$box" > "$T/seed.json"
for s in fov seed; do
  "$BIN" compare "$T/$s.json" --methods spheres -W 128 -H 128 --repeat 1 -q -o "$T/$s" 2> /dev/null
done
check 'ref_stage fov march && ref_stage seed march && [ "$(entries)" -eq $((n0 + 3)) ]' "a changed camera or particle set misses"
cmpr size -W 120
check 'ref_stage size march' "a changed image size misses"

# 3. a corrupt entry is rendered again, with one warning, and replaced
bytes=$(stat -c %s "$entry")
head -c $((bytes / 2)) "$entry" > "$T/half.exr" && mv "$T/half.exr" "$entry"
"$BIN" compare "$box" --methods spheres -W 128 -H 128 --repeat 1 -o "$T/trunc" 2> "$T/trunc.err"; rc=$?
check '[ $rc -eq 0 ] && [ "$(grep -c "^fluidsurf: warning: bad cache entry, rendering it again: $entry" "$T/trunc.err")" -eq 1 ]' "a truncated entry warns in one line"
check 'ref_stage trunc march && [ "$(metrics trunc)" = "$(metrics miss)" ] && same_images miss trunc' "a truncated entry is rendered again, identical metrics and images"
cmpr after; check 'ref_stage after cache' "the rendered entry replaced the truncated one"
python3 -c "
import sys; p = sys.argv[1]; d = bytearray(open(p, 'rb').read())
for i in range(len(d) // 2, len(d) // 2 + 64): d[i] ^= 0x5a
open(p, 'wb').write(d)" "$entry"
"$BIN" compare "$box" --methods spheres -W 128 -H 128 --repeat 1 -o "$T/flip" 2> "$T/flip.err"; rc=$?
check '[ $rc -eq 0 ] && grep -q "^fluidsurf: warning: bad cache entry" "$T/flip.err" && ref_stage flip march && [ "$(metrics flip)" = "$(metrics miss)" ]' "a byte-flipped entry is rendered again, identical metrics"
cmpr flipq; check '[ ! -s "$T/flipq.err" ]' "-q: no line for a hit"
other=$(find "$C" -name 'gbuffer-*.exr' ! -path "$entry" | head -1)
cp "$other" "$entry"   # another key under this name: a stale entry or a collision
cmpr stale; check 'ref_stage stale march && [ "$(metrics stale)" = "$(metrics miss)" ]' "an entry holding another key is not trusted"

# 4. a folder that cannot be made or written: one warning, the run goes on
touch "$T/file"
cmpr nofolder --cache "$T/file/sub"; rc=$?
check '[ $rc -eq 0 ] && [ "$(wc -l < "$T/nofolder.err")" -eq 1 ] && grep -q "^fluidsurf: warning: $T/file/sub: .*continuing without the cache" "$T/nofolder.err"' "an unusable cache folder: one warning naming it (even with -q)"
check '[ "$(metrics nofolder)" = "$(metrics miss)" ] && grep -q "rendered; no cache" "$T/nofolder/report.md" && ! ref_stage nofolder cache_store' "and the run goes on without the cache"

# 5. --no-cache and render: the default folder stays untouched (Mesa keeps its
# own shader cache in $XDG_CACHE_HOME/mesa_shader_cache)
export XDG_CACHE_HOME=$T/xdg2; mkdir -p "$XDG_CACHE_HOME"
cmpr nocache --no-cache; rc=$?
check '[ $rc -eq 0 ] && [ ! -e "$XDG_CACHE_HOME/fluidsurf" ] && grep -q "rendered; no cache (turned off)" "$T/nocache/report.md"' "--no-cache writes nothing"
"$BIN" render "$box" -W 128 -H 128 -q -o "$T/r0.exr"; rc=$?
check '[ $rc -eq 0 ] && [ ! -e "$XDG_CACHE_HOME/fluidsurf" ]' "render without --cache does not touch the default cache"
"$BIN" render "$box" -W 128 -H 128 --cache "$T/rc" --timings -o "$T/r1.exr" > "$T/r1.t" 2> "$T/r1.err"
"$BIN" render "$box" -W 128 -H 128 --cache "$T/rc" --timings -o "$T/r2.exr" > "$T/r2.t" 2> "$T/r2.err"; rc=$?
check '[ $rc -eq 0 ] && grep -q "^march," "$T/r1.t" && grep -q "^cache," "$T/r2.t" && ! grep -q "^march," "$T/r2.t"' "render --cache DIR: a miss, then a hit timed as cache"
check 'grep -q "^fluidsurf: note: reference from the cache, $T/rc/gbuffer-" "$T/r2.err" && idiff -q "$T/r0.exr" "$T/r2.exr" > /dev/null 2>&1' "render's hit is named and gives the same EXR"

# 6. a sequence: one entry per frame
export XDG_CACHE_HOME=$T/xdg3
printf '{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 2}, "radius": 0.025}' > "$T/seq.json"
for d in seq1 seq2; do "$BIN" compare "$T/seq.json" --methods spheres -W 40 -H 40 --repeat 1 -q -o "$T/$d" 2> /dev/null; done
check '[ "$(find "$T/xdg3/fluidsurf" -name "gbuffer-*.exr" | wc -l)" -eq 3 ] && grep -q "3 of 3 frame(s) from the cache" "$T/seq2/report.md" && grep -q "frame 2: from the cache:" "$T/seq2/report.md"' "a sequence: an entry per frame, every frame a hit the second time"
check '[ "$(grep -v "^#" "$T/seq1/temporal.csv")" = "$(grep -v "^#" "$T/seq2/temporal.csv")" ] && [ "$(metrics seq1)" = "$(metrics seq2)" ]' "a sequence from the cache: identical metrics and temporal.csv"

# 6. bad usage
"$BIN" compare "$box" --methods spheres --cache "$T/c" --no-cache -o "$T/both" 2> "$T/both.err"; rc=$?
check '[ $rc -eq 2 ] && [ ! -e "$T/both" ] && [ ! -e "$T/c" ]' "--cache with --no-cache: usage error, nothing made"
"$BIN" render "$box" --method spheres --cache "$T/c" -o "$T/s.png" 2> /dev/null; rc=$?
check '[ $rc -eq 2 ] && [ ! -e "$T/c" ]' "render --cache with a method other than reference: usage error"

echo "$fails failed"
[ $fails -eq 0 ]
