#!/usr/bin/env bash
# Peak memory of compare on a long sequence (issue 34: frames stream). A frame
# pattern over N copies (symlinks) of one frame, compared with spheres (GL) and
# the reference at 64x64: the executor holds one frame and each view's current and
# previous G-buffer, so peak RSS must not grow with N. Writes
# $RESULTS/study/stream_rss.csv (frames,max_rss_kb,wall_s,items) and its README block.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${BIN:-./build/fluidsurf}
FRAME=experiments/data/splashsurf/cube_2366_particles.vtk
out=$RESULTS/study; work=out/stream_rss
mkdir -p "$out" "$work"
csv=$out/stream_rss.csv
counts=$(quick "100 1000" "10 30")
max=$(tr ' ' '\n' <<< "$counts" | sort -n | tail -1)
for ((f = 0; f < max; f++)); do ln -sf "$PWD/$FRAME" "$work/f_$(printf %04d $f).vtk"; done
{
  echo "# $STUDY_PROV; compare of spheres and the reference, 64x64, --repeat 1, --no-cache, on N symlinked copies of $FRAME; /usr/bin/time max RSS"
  echo "frames,max_rss_kb,wall_s,items"
  for n in $counts; do
    printf '{"particles": {"file": "%s/f_%%04d.vtk", "first": 0, "last": %d}, "radius": 0.025}\n' "$PWD/$work" $((n - 1)) > "$work/seq.json"
    /usr/bin/time -f "%M %e" -o "$work/time.txt" "$BIN" compare "$work/seq.json" --methods spheres -W 64 -H 64 \
      --repeat 1 --no-cache -q --force -o "$work/out_$n"
    read -r rss wall < "$work/time.txt"
    items=$(($(grep -vc "^#" "$work/out_$n/metrics.csv") - 1))
    echo "$n,$rss,$wall,$items"
  done
} > "$csv.tmp"
publish "$csv"
cat "$csv"
