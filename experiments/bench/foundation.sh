#!/usr/bin/env bash
# Foundation benchmark (issue: load + grid build, reference and spheres frame
# times, peak memory). Writes results/bench/foundation.csv with a provenance
# header. Medians of RUNS runs (default 5) of the whole command; every row names
# the renderer its GL stages ran on.
# FS_QUICK=1 (run_all.sh --quick): 64^2 and 128^2 images, a 27k box, 1 run, into
# out/quick/results/bench (work files in out/quick/bench).
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, quick, RESULTS
RUNS=${RUNS:-$(quick 5 1)}
BIN=${BIN:-./build/fluidsurf}
[ -x "$BIN" ] || bash scripts/build.sh build
S1=$(quick 512 64) S2=$(quick 1024 128)                # the image sizes
BOX=$(quick 100 30) BOXN=$(quick 1m 27k)               # the box's side and its name
WORK=$(quick out/bench out/quick/bench)
out=$RESULTS/bench/foundation.csv
mkdir -p "$RESULTS/bench" "$WORK"
tmp=$(mktemp)

if [ "$FS_QUICK" = 1 ]; then
  printf '{"description": "synthetic %d^3-particle box, r = 0.025 (quick)",\n "particles": {"synthetic": "box", "size": [%d, %d, %d], "jitter": 0.1, "seed": 1},\n "radius": 0.025}\n' \
    "$BOX" "$BOX" "$BOX" "$BOX" > "$WORK/box$BOXN.json"
else
cat > "$WORK/box1m.json" <<'JSON'
{"description": "synthetic 100^3 = 1,000,000-particle box, r = 0.025",
 "particles": {"synthetic": "box", "size": [100, 100, 100], "jitter": 0.1, "seed": 1},
 "radius": 0.025}
JSON
fi
dam=experiments/scenes/dam_break.json
box=$WORK/box$BOXN.json

# bench LABEL SCENE METHOD SIZE: runs the render RUNS times, collects each stage's
# median and the peak resident memory (max over runs).
bench() {
  local label=$1 scene=$2 method=$3 size=$4
  rm -f "$tmp".*
  for i in $(seq "$RUNS"); do
    /usr/bin/time -f "%M" -o "$tmp.mem" "$BIN" render "$scene" --method "$method" -W "$size" -H "$size" \
        --timings -q -o "$WORK/$label.png" > "$tmp.run"
    cat "$tmp.mem" >> "$tmp.mems"
    tail -n +2 "$tmp.run" >> "$tmp.stages"
  done
  local peak renderer
  peak=$(sort -g "$tmp.mems" | tail -1)
  for stage in $(cut -d, -f1 "$tmp.stages" | awk '!seen[$0]++'); do
    renderer=$(grep "^$stage," "$tmp.stages" | head -1 | cut -d, -f4-)
    med=$(grep "^$stage," "$tmp.stages" | cut -d, -f2 | median)
    echo "$label,$method,$size,$stage,$med,$RUNS,$peak,\"$renderer\"" >> "$out.tmp"
    printf '%-28s %-10s %5s %-10s %10.2f ms  peak %s KiB  (%s)\n' "$label" "$method" "$size" "$stage" "$med" "$peak" "$renderer"
  done
}

{
  echo "# fluidsurf foundation benchmark; $STUDY_PROV; $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "# machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
  echo "# medians of $RUNS runs; peak_rss_kib is the largest over the runs (whole process)"
  echo "scene,method,size,stage,ms_median,runs,peak_rss_kib,renderer"
} > "$out.tmp"
bench dam_break_24k_ref$S1 $dam reference $S1
bench dam_break_24k_sph$S1 $dam spheres $S1
bench dam_break_24k_sph$S2 $dam spheres $S2
bench box_${BOXN}_ref$S1 $box reference $S1
bench box_${BOXN}_sph$S1 $box spheres $S1
bench box_${BOXN}_sph$S2 $box spheres $S2
publish "$out"
stamp_csv "$out"
rm -f "$tmp" "$tmp".*
echo "wrote $out"
