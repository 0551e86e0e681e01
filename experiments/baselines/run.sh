#!/usr/bin/env bash
# The baselines study (issue 15): levelset and mesh against the reference on the
# bundled dam break, the mesh's convergence as cube shrinks, and the speed and
# peak memory of `fluidsurf mesh` and of `levelset` against OpenVDB's vdb_tool
# whole pipeline on the same frames, measured in the same run (medians of RUNS).
#
#   experiments/baselines/run.sh [-o DIR] [--sets "dam splash_seq box_100k box_1m box_10m"]
#                                [--render-sets "dam splash box_1m"]
#
# Sets: dam (the bundled splashsurf frame), splash_seq (frames 6-10 of fluidsurf's
# own 100k dam break simulation, made once into FS_BENCH_CACHE: 15-30 minutes),
# splash (its frame 10, committed as experiments/data/splash/), box_* (synthetic
# scenes of experiments/scenes/). Writes DIR (default results/baselines):
# quality.csv, convergence.csv, speed.csv (one row per tool, set and run: wall s,
# peak RSS), stages.csv (fluidsurf mesh --timings), render.csv (levelset against
# vdb_tool -render, the same view) with render_stages.csv (levelset's --timings),
# convergence.png, and README.md from them.
# FS_QUICK=1 (run_all.sh --quick): 128x128, 1 run, cube 1 and 0.5 r, sets dam, a 2-frame
# splash_seq of about 3,000 particles (simulated into out/quick/baselines, a few seconds) and
# boxes of 8k and 27k particles; render sets dam and the 27k box; into out/quick/results/baselines.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # median, auto_camera, vdb_aperture, quick, RESULTS, study_commit
OUT=$RESULTS/baselines
SETS=$(quick "dam splash_seq box_100k box_1m box_10m" "dam splash_seq box_8k box_27k")
RENDER_SETS=$(quick "dam splash box_1m" "dam box_27k")
while [ $# -gt 0 ]; do
  case $1 in
    -o) OUT=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    --render-sets) RENDER_SETS=$2; shift 2 ;;
    *) echo "usage: $0 [-o DIR] [--sets \"dam splash_seq box_100k box_1m box_10m\"] [--render-sets \"dam splash box_1m\"]" >&2; exit 2 ;;
  esac
done
CACHE=${FS_BENCH_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/fluidsurf-bench}
SEQ=$(quick "$CACHE/splash_seq" out/quick/baselines/splash_seq) # frames f_0006.ply .. f_0010.ply (quick: f_0001, f_0002)
SEQ_PARTICLES=$(quick 100000 3000)
SEQ_FIRST=$(quick 6 1) SEQ_LAST=$(quick 10 2)
SIZE=${SIZE:-$(quick 1024 128)} # levelset against vdb_tool -render
BIN=${BIN:-./build/fluidsurf}
RUNS=${RUNS:-$(quick 3 1)}
[ -x "$BIN" ] || bash scripts/build.sh "$(dirname "$BIN")"
command -v vdb_tool > /dev/null || { echo "run.sh: vdb_tool (libopenvdb-tools) is needed" >&2; exit 1; }
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prov="# $(study_commit); cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); cores=$(nproc); vdb_tool=$(dpkg-query -W -f '${Version}' libopenvdb-tools 2>/dev/null || echo unknown); date=$(date -u +%F)"

# ---- quality: the dam break at 512x512, levelset and mesh (plain and Taubin) against the reference
QSIZE=$(quick "" "-W $SIZE -H $SIZE") # quick: the compare images at SIZE (full: the scene's 512x512)
"$BIN" compare experiments/scenes/dam_break.json --methods reference,levelset,mesh --no-cache -q --repeat 1 \
  $QSIZE -o "$tmp/q" > /dev/null
"$BIN" compare experiments/scenes/dam_break.json --methods mesh --set mesh.smooth=taubin --no-cache -q --repeat 1 \
  $QSIZE -o "$tmp/qs" > /dev/null
{ echo "$prov"; grep -v '^#' "$tmp/q/metrics.csv"; grep -v '^#' "$tmp/qs/metrics.csv" | awk -F, -v OFS=, 'NR > 1 && $1 == "mesh" {$2 = "smooth=taubin"; print}'; } > "$OUT/quality.csv"

# ---- convergence: mesh against the reference as cube shrinks from 1 r to 0.25 r
"$BIN" compare experiments/scenes/dam_break.json --methods mesh --set mesh.cube=$(quick 1,0.75,0.5,0.35,0.25 1,0.5) --no-cache -q \
  --repeat 1 $QSIZE -o "$tmp/c" > /dev/null
{ echo "$prov"; grep -v '^#' "$tmp/c/metrics.csv" | awk -F, 'NR == 1 || $1 == "mesh"'; } > "$OUT/convergence.csv"
if command -v gnuplot > /dev/null; then
  csv_awk 'split(col("variant"), a, "="); print a[2], col("depth_rmse_r"), col("depth_p95_r")' "$OUT/convergence.csv" > "$tmp/conv.dat"
  gnuplot <<GP
set terminal pngcairo size 640,420
set output "$OUT/convergence.png"
set title "mesh against reference, dam break $(quick 512x512 "${SIZE}x$SIZE")"
set xlabel "cube (multiples of r)"; set ylabel "depth error (r)"; set logscale xy; set key top left
plot "$tmp/conv.dat" using 1:2 with linespoints title "depth RMSE", "" using 1:3 with linespoints title "depth p95"
GP
fi

# ---- speed and memory: the same PLY for every tool; wall time and peak RSS of the whole process
set_file() { # NAME -> the PLY path (splash_seq: the frame pattern)
  case $1 in
    dam) echo experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply ;;
    splash) echo experiments/data/splash/dam_break_splash_100k.ply ;;
    splash_seq)
      if [ ! -s "$(printf '%s/f_%04d.ply' "$SEQ" $SEQ_LAST)" ]; then
        echo "run.sh: simulating the splash sequence into $SEQ (once; $(quick "15-30 minutes" "quick: seconds"))" >&2
        mkdir -p "$SEQ"
        "$BIN" simulate dam_break --cpu --particles $SEQ_PARTICLES --fps 10 --frames $SEQ_LAST -q -o "$SEQ/f_%04d.ply" >&2
      fi
      echo "$SEQ/f_%04d.ply" ;;
    *) [ -s "$tmp/$1.ply" ] || "$BIN" convert "$(scene_of "$1")" -o "$tmp/$1.ply" >&2; echo "$tmp/$1.ply" ;;
  esac
}
# scene_of NAME: experiments/scenes/NAME.json; quick mode's boxes (box_8k, box_27k: 20^3 and 30^3,
# the lattice of box_100k) are written into $tmp/scenes
scene_of() {
  local side
  case $FS_QUICK:$1 in
    1:box_8k) side=20 ;;
    1:box_27k) side=30 ;;
    *) echo "experiments/scenes/$1.json"; return ;;
  esac
  mkdir -p "$tmp/scenes"
  printf '{"particles": {"synthetic": "box", "size": [%d, %d, %d], "jitter": 0.1, "seed": 1}, "radius": 0.025}\n' \
    $side $side $side > "$tmp/scenes/$1.json"
  echo "$tmp/scenes/$1.json"
}
frames_of() { # PLY (or pattern) -> the frame files, one per line
  if [ "$1" = "${1/\%04d/}" ]; then echo "$1"; else for f in $(seq $SEQ_FIRST $SEQ_LAST); do printf "$1\n" "$f"; done; fi
}
# the vdb_tool pipeline over every frame, in one timed shell: vdb_points ARGS... -- FILES...
VDB_LOOP='args=(); while [ "$1" != -- ]; do args+=("$1"); shift; done; shift
for f in "$@"; do vdb_tool -read "$f" "${args[@]}" || exit 1; done'
timed() { # SET TOOL RUN CMD...: appends a speed.csv row
  local set=$1 tool=$2 run=$3; shift 3
  /usr/bin/time -f "%e %M" -o "$tmp/time" "$@" > "$tmp/stdout" 2> "$tmp/stderr" || { echo "run.sh: $tool on $set failed: $(tail -2 "$tmp/stderr")" >&2; return 1; }
  read -r wall kb < "$tmp/time"
  echo "$set,$tool,$run,$N,$F,$wall,$kb" >> "$CSV"
}
CSV=$OUT/speed.csv
{ echo "$prov"; echo "set,tool,run,particles,frames,wall_s,peak_rss_kb"; } > "$CSV"
{ echo "$prov"; echo "set,settings,run,frame,stage,ms,vertices,triangles"; } > "$OUT/stages.csv"
r=0.025
vox=$(awk -v r=$r 'BEGIN {print r / 2}')
for set in $SETS; do
  ply=$(set_file "$set")
  mapfile -t files < <(frames_of "$ply")
  F=${#files[@]}
  N=$("$BIN" info "${files[0]}" --radius $r | awk '/^particles:/ {print $2}')
  io=("$ply"); out=$tmp/m.ply
  [ "$F" = 1 ] || { io+=(--frames $SEQ_FIRST:$SEQ_LAST); out=$tmp/m_{}.ply; }
  for run in $(seq 1 "$RUNS"); do
    # one run of each tool in turn, so load on the machine hits them alike
    timed "$set" "fluidsurf mesh" "$run" "$BIN" mesh "${io[@]}" --radius $r -q --timings -o "$out"
    sed "s/^/$set,cube=0.5,$run,/" "$tmp/stdout" | tail -n +2 >> "$OUT/stages.csv"
    timed "$set" "vdb_tool points2ls+ls2mesh" "$run" bash -c "$VDB_LOOP" _ -points2ls voxel=$vox radius=4 width=3 \
      -ls2mesh -write "$tmp/v.ply" -- "${files[@]}"
    timed "$set" "vdb_tool points2ls" "$run" bash -c "$VDB_LOOP" _ -points2ls voxel=$vox radius=4 width=3 -- "${files[@]}"
    timed "$set" "fluidsurf mesh cube=1.5" "$run" "$BIN" mesh "${io[@]}" --radius $r -q --timings --set mesh.cube=1.5 -o "$out"
    sed "s/^/$set,cube=1.5,$run,/" "$tmp/stdout" | tail -n +2 >> "$OUT/stages.csv"
    timed "$set" "fluidsurf startup" "$run" "$BIN" --version
  done
done

# ---- levelset (thickness off, its defaults: voxel r/2, radius 2r = 4 voxels, half width 3) against
# vdb_tool -points2ls voxel=r/2 radius=4 width=3 -render, the same view (the camera fluidsurf frames
# the set with) and the same SIZE x SIZE image; the last run's images stay in out/baselines/
CSV=$OUT/render.csv
{ echo "$prov; image=${SIZE}x$SIZE"; echo "set,tool,run,particles,frames,wall_s,peak_rss_kb"; } > "$CSV"
{ echo "$prov; image=${SIZE}x$SIZE"; echo "set,run,stage,ms"; } > "$OUT/render_stages.csv"
F=1 IMG=$(quick out/baselines out/quick/baselines)
mkdir -p "$IMG"
for set in $RENDER_SETS; do
  ply=$(realpath "$(set_file "$set")")
  printf '{"particles": "%s", "radius": %s}\n' "$ply" $r > "$tmp/$set.json"
  auto_camera "$BIN" "$tmp/$set.json" "$tmp"
  printf '{"particles": "%s", "radius": %s, "camera": {%s, "width": %d, "height": %d}}\n' \
    "$ply" $r "$P_CAMERA" "$SIZE" "$SIZE" > "$tmp/$set.json"
  N=$("$BIN" info "$ply" --radius $r | awk '/^particles:/ {print $2}')
  for run in $(seq 1 "$RUNS"); do
    timed "$set" "levelset" "$run" "$BIN" render "$tmp/$set.json" --method levelset --set levelset.thickness=off -q \
      --timings -o "$IMG/${set}_levelset.png"
    awk -F, -v s="$set" -v r="$run" 'NR > 1 {print s "," r "," $1 "," $2}' "$tmp/stdout" >> "$OUT/render_stages.csv"
    timed "$set" "vdb_tool points2ls+render" "$run" vdb_tool -read "$ply" -points2ls voxel=$vox radius=4 width=3 \
      -render image="${SIZE}x$SIZE" translate="($P_EYE)" target="($P_TGT)" up="($P_UP)" aperture="$(vdb_aperture "$FOV")" \
      "$IMG/${set}_vdb_tool.png"
  done
done
bash experiments/baselines/report.sh "$OUT"
echo "run.sh: wrote $OUT"
