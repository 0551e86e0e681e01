#!/usr/bin/env bash
# xiao2017 Fig. 10 analogue: raycast_pca frame time against the iso value.
# The paper sweeps 10..30 around its middle 20 (0.5..1.5 of the middle value);
# on fluidsurf's normalised phi that is 0.3..0.9 around the default 0.6
# (methods/raycast_pca/README.md). Scenes: the 24k dam break and the 300k box,
# SIZE^2 (default 512), medians of RUNS (default 3) of the frame time (sum of
# splat..readback) and of the march stage. Writes results/xiao2017/fig10.csv.
# FS_QUICK=1 (experiments/lib.sh): 128^2, 1 run, iso 0.4 and 0.8, a synthetic 20^3 box
# (8,000 particles) for the 300k box; into out/quick/results/xiao2017 and out/quick/xiao2017/fig10.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, RESULTS, quick, study_commit
BIN=${BIN:-./build/fluidsurf}
SIZE=${SIZE:-$(quick 512 128)}
RUNS=${RUNS:-$(quick 3 1)}
ISOS=${ISOS:-$(quick "0.3 0.4 0.5 0.6 0.7 0.8 0.9" "0.4 0.8")}
OUT=$RESULTS/xiao2017
TMP=out/$(quick "" quick/)xiao2017/fig10
mkdir -p "$OUT" "$TMP"
[ -x "$BIN" ] || { echo "fig10.sh: $BIN missing" >&2; exit 2; }
STAGES=" splat march normals filter thickness readback "
SPECS="dam_break_24k:24389:experiments/scenes/dam_break.json box_300k:300763:experiments/scenes/box_300k.json"
if [ "$FS_QUICK" = 1 ]; then
  echo '{"particles": {"synthetic": "box", "size": [20, 20, 20], "jitter": 0.1, "seed": 1}, "radius": 0.025,
 "material": "water", "background": "checker", "camera": {"width": 128, "height": 128}}' > "$TMP/box_8k.json"
  SPECS="dam_break_24k:24389:experiments/scenes/dam_break.json box_8k:8000:$TMP/box_8k.json"
fi

csv=$OUT/fig10.csv
{
  echo "# xiao2017 Fig. 10 analogue; $STUDY_PROV; $(date -u +%Y-%m-%dT%H:%MZ); $(nproc) cores"
  echo "# raycast_pca shipped defaults, ${SIZE}x${SIZE}, medians of $RUNS runs; frame = sum of splat..readback"
  echo "scene,particles,iso,frame_ms,march_ms,runs,renderer"
} > "$csv.tmp"
for spec in $SPECS; do
  IFS=: read -r label n scene <<< "$spec"
  for iso in $ISOS; do
    # A copy of the scene with another iso value (particle paths made absolute).
    s=$TMP/${label}_iso$iso.json
    python3 - "$scene" "$iso" > "$s" <<'PY'
import json, os, sys
path, iso = sys.argv[1], float(sys.argv[2])
d = json.load(open(path))
if isinstance(d.get("particles"), str):
    d["particles"] = os.path.abspath(os.path.join(os.path.dirname(path), d["particles"]))
d["iso"] = iso
json.dump(d, sys.stdout, indent=1)
PY
    rm -f "$TMP"/run.*
    for i in $(seq "$RUNS"); do
      "$BIN" render "$s" --method raycast_pca -W "$SIZE" -H "$SIZE" --timings -q -o "$TMP/last.png" > "$TMP/run.$i"
    done
    frame=$(for r in "$TMP"/run.*; do awk -F, -v st="$STAGES" 'index(st, " " $1 " ") {s += $2} END {print s}' "$r"; done | median)
    march=$(cat "$TMP"/run.* | grep '^march,' | cut -d, -f2 | median)
    renderer=$(grep -h '^march,' "$TMP/run.1" | cut -d, -f4-)
    echo "$label,$n,$iso,$frame,$march,$RUNS,\"$renderer\"" >> "$csv.tmp"
    printf '%-14s iso %.1f  frame %8.1f ms  march %8.1f ms\n' "$label" "$iso" "$frame" "$march"
  done
done
publish "$csv"
echo "wrote $csv"
