#!/usr/bin/env bash
# Speed and memory benchmark of issue 13 ("A benchmark that runs the peer in the
# same run"): whole-process wall time and peak RSS of fluidsurf's methods, of
# fluidsurf's reference at the baseline commit (a548d02) and of OpenVDB's
# vdb_tool (points -> level set -> ray trace), on the same particles and the
# same view, in one run.
#
#   experiments/bench/speed.sh           full: 1024x1024, medians of 3 runs;
#                                        writes results/bench/speed.csv,
#                                        speed_ratios.csv, speed.png, README-speed.md
#   experiments/bench/speed.sh --quick   smoke check (also FS_QUICK=1, run_all.sh --quick): small
#                                        sets, 128x128, 1 run, today's binary standing in for the
#                                        baseline (which is not built); writes the same files under
#                                        out/quick/results/bench/ (work and cache in out/quick/bench/)
#
# Environment: RUNS, SIZE (override the mode's), BIN (default ./build/fluidsurf,
# built when missing), FS_BENCH_CACHE (where the baseline build and the particle
# files live; default ${XDG_CACHE_HOME:-~/.cache}/fluidsurf-bench), BASE_COMMIT
# (default a548d02), BASE_SETS (sets the baseline runs on; default "splash
# dam_break_24k"), SETS (restrict to these set names), RUNS_10M (runs on the 10M
# box; default RUNS), SKIP_10M=1 (full mode
# without the 10M box), SHARED (the shared data folder with the DualSPHysics frame;
# default ../shared/data), LEVELSET_SETS (sets that also time fluidsurf's levelset;
# default "dualsphysics splash dam_break_24k"). Progress goes to stderr.
#
# Sets: synthetic boxes, the bundled SPlisHSPlasH frames, fluidsurf's splash frame and
# (full mode) the third-party DualSPHysics dam break just after impact (205k particles,
# z up, r = 0.00365 as its README gives; SHARED/dualsphysics/dambreak200k_t0.300.vtk).
# The fixed cost is timed at 8x8 pixels on the splash frame (EXR) and on the 6,859-particle
# dam break (EXR and PNG: \`reference\` and \`reference to PNG\`).
#
# What is timed: the whole process, by /usr/bin/time (%e wall s, %M peak RSS KiB).
# fluidsurf writes an EXR (G-buffer + shaded image); vdb_tool reads a PLY of the
# same points (written beforehand, untimed) and writes a PNG. Every fluidsurf
# binary gets a scene file with the camera written out: the one that today's
# fluidsurf frames automatically for the set (read back from its EXR provenance),
# so the baseline and vdb_tool see exactly that view even if framing changes.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD

QUICK=0
case "${1:-}" in
  --quick) export FS_QUICK=1 ;;
  "") ;;
  -h|--help) sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "usage: $0 [--quick]" >&2; exit 2 ;;
esac
source experiments/lib.sh # median, auto_camera, vdb_aperture, quick, RESULTS, study_commit
# The tree the binaries were built from, taken once at the start: an edit made while the
# benchmark runs does not change what it measures.
PROV=$STUDY_PROV
[ "$FS_QUICK" = 1 ] && QUICK=1
RUNS=${RUNS:-$(quick 3 1)}; SIZE=${SIZE:-$(quick 1024 128)}; OUT=$RESULTS/bench
BIN=${BIN:-./build/fluidsurf}
BASE_COMMIT=${BASE_COMMIT:-a548d02}
BASE_SETS=${BASE_SETS:-splash dam_break_24k}
CACHE=${FS_BENCH_CACHE:-$(quick "${XDG_CACHE_HOME:-$HOME/.cache}/fluidsurf-bench" out/quick/bench/cache)}
WORK=$(quick out/bench/speed out/quick/bench/speed) # images and scene files (not committed)
VDB_TOOL=${VDB_TOOL:-vdb_tool}
SPLASH=experiments/data/splash/dam_break_splash_100k.ply
SHARED=${SHARED:-../shared/data}
DSPH=$SHARED/dualsphysics/dambreak200k_t0.300.vtk
mkdir -p "$OUT" "$WORK" "$CACHE/sets"
T0=$(date +%s)
log() { printf '[speed %4ds] %s\n' $(($(date +%s) - T0)) "$*" >&2; }

[ -x "$BIN" ] || { log "building $BIN"; bash scripts/build.sh "$(dirname "$BIN")" >&2; }
command -v "$VDB_TOOL" >/dev/null || { echo "speed.sh: $VDB_TOOL not found (Debian libopenvdb-tools)" >&2; exit 1; }
command -v iinfo >/dev/null && command -v oiiotool >/dev/null ||
  { echo "speed.sh: iinfo/oiiotool not found (Debian openimageio-tools)" >&2; exit 1; }

# ---- the baseline: BASE_COMMIT built once into the cache, Release with debug
# info as scripts/build.sh builds (its source from git archive, so no worktree
# or branch of this repository is touched)
BASE_FULL=$(git rev-parse "$BASE_COMMIT^{commit}")
BASE_DIR=$CACHE/base-${BASE_FULL:0:12}
BASE_BIN=$BASE_DIR/build/fluidsurf
BASE_DESC="$BASE_FULL built RelWithDebInfo (as scripts/build.sh) in $BASE_DIR"
if [ $QUICK = 1 ]; then # the smoke check: today's binary stands in for the baseline (its rows and ratios run)
  BASE_BIN=$BIN
  BASE_DESC="today's $BIN standing in (quick: $BASE_FULL is not built)"
elif [ ! -x "$BASE_BIN" ]; then
  log "building the baseline $BASE_COMMIT into $BASE_DIR (once)"
  rm -rf "$BASE_DIR"; mkdir -p "$BASE_DIR/src"
  git archive "$BASE_FULL" | tar -x -C "$BASE_DIR/src"
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$BASE_DIR/src" -B "$BASE_DIR/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" >"$BASE_DIR/build.log" 2>&1 &&
    cmake --build "$BASE_DIR/build" -j"$(nproc)" --target fluidsurf >>"$BASE_DIR/build.log" 2>&1 ||
    { echo "speed.sh: the baseline build failed; see $BASE_DIR/build.log" >&2; exit 1; }
fi

# ---- the particle sets: NAME KIND SOURCE (KIND synthetic: SOURCE is "nx ny nz")
# EXTRA: scene keys the set needs beyond its file (its up axis, its radius)
declare -a SET_NAMES=() SET_KIND=() SET_SRC=() SET_EXTRA=()
add_set() { SET_NAMES+=("$1"); SET_KIND+=("$2"); SET_SRC+=("$3"); SET_EXTRA+=("${4:-}"); }
D=experiments/data/splashsurf
if [ $QUICK = 1 ]; then
  add_set splash file "$SPLASH"
  add_set box_1k synthetic "10 10 10"
  add_set box_10k synthetic "22 22 22"
  add_set box_27k synthetic "30 30 30"
  add_set cube_2k file "$D/cube_2366_particles.vtk"
  add_set dam_break_7k file "$D/dam_break_frame_9_6859_particles.bgeo"
  GROWTH="box_1k box_10k box_27k"
  LEVELSET_SETS=${LEVELSET_SETS:-splash}
else
  # the targets' sets first, so a run cut short still has them. (fluid_250_particles.vtu is left
  # out: it gives no r, and at the default r = 0.025 its 250 sparse particles make no surface.)
  add_set dualsphysics file "$DSPH" '"up": "z", "radius": 0.00365'
  add_set splash file "$SPLASH"
  add_set dam_break_24k file "$D/dam_break_frame_23_24389_particles.vtk"
  add_set box_100k synthetic "46 46 46"
  add_set box_1m synthetic "100 100 100"
  [ "${SKIP_10M:-0}" = 1 ] || add_set box_10m synthetic "215 215 215"
  add_set cube_2k file "$D/cube_2366_particles.vtk"
  add_set double_dam_break_5k file "$D/double_dam_break_frame_26_4732_particles.vtk"
  add_set dam_break_7k file "$D/dam_break_frame_9_6859_particles.bgeo"
  GROWTH="box_100k box_1m box_10m"
  LEVELSET_SETS=${LEVELSET_SETS:-dualsphysics splash dam_break_24k}
fi

# prepare_set I: writes $WORK/NAME.json (particles + r + the camera written out)
# and $CACHE/sets/NAME.ply (the points for vdb_tool); sets P_N, P_R, P_EYE, P_TGT, P_UP
prepare_set() {
  local i=$1 name=${SET_NAMES[$1]} kind=${SET_KIND[$1]} src=${SET_SRC[$1]} extra=${SET_EXTRA[$1]:+, ${SET_EXTRA[$1]}} part
  if [ "$kind" = synthetic ]; then
    read -r nx ny nz <<<"$src"
    part="{\"synthetic\": \"box\", \"size\": [$nx, $ny, $nz], \"jitter\": 0.1, \"seed\": 1}, \"radius\": 0.025"
  else
    part="\"$(realpath "$src")\""
  fi
  # today's auto-framed camera at this aspect (framing depends on the aspect, not the size)
  printf '{"description": "speed benchmark set %s", "particles": %s%s}\n' "$name" "$part" "$extra" > "$WORK/$name.auto.json"
  auto_camera "$BIN" "$WORK/$name.auto.json" "$WORK"
  if [ -n "$extra" ]; then part="$part$extra"; elif [ "$kind" != synthetic ]; then part="$part, \"radius\": $P_R"; fi
  printf '{"description": "speed benchmark set %s, camera as fluidsurf %s frames it",\n "particles": %s,\n "camera": {%s, "width": %d, "height": %d}}\n' \
    "$name" "$(git rev-parse --short HEAD)" "$part" "$P_CAMERA" "$SIZE" "$SIZE" > "$WORK/$name.json"
  local ply=$CACHE/sets/$name.ply key
  key=$(printf '%s|%s' "$part" "$( [ "$kind" = file ] && stat -c '%s %Y' "$src")" | md5sum | cut -c1-12)
  if [ ! -s "$ply" ] || [ "$(cat "$ply.key" 2>/dev/null)" != "$key" ]; then
    "$BIN" convert "$WORK/$name.auto.json" -o "$ply"
    echo "$key" > "$ply.key"
  fi
  P_N=$("$BIN" info "$ply" | sed -n 's/^particles: //p')
}

# coverage FILE: fraction of covered pixels (EXR: the coverage layer; vdb_tool's
# PNG: pixels that are not black, its background)
coverage() {
  local stats
  case "$1" in
    *.exr) stats=$(oiiotool "$1" --ch coverage --printstats 2>/dev/null) ;;
    *) stats=$(oiiotool "$1" --ch R --mulc 255 --clamp:min=0:max=1 --printstats 2>/dev/null) ;;
  esac
  sed -n 's/^ *Stats Avg: \([^ ]*\).*/\1/p' <<<"$stats" | head -1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
CSV=$OUT/speed.csv
RENDERER=""
# bench SET N METHOD W H IMG CMD...: RUNS whole-process runs; one CSV row
bench() {
  local set=$1 n=$2 method=$3 w=$4 h=$5 img=$6; shift 6
  local walls=() rss=() stage=() status=ok err="" k
  for k in $(seq "$NRUNS"); do
    rm -f "$img"
    if /usr/bin/time -f '%e %M' -o "$tmp/time" "$@" > "$tmp/stdout" 2> "$tmp/stderr"; then
      read -r wall kib < <(tail -1 "$tmp/time")
      walls+=("$wall"); rss+=("$kib")
      # the method's own stages from --timings: all but load, grid, upload, shade
      if grep -q '^stage,ms' "$tmp/stdout"; then
        stage+=("$(awk -F, 'NR > 1 && $1 !~ /^(load|grid|upload|shade)$/ {s += $2} END {printf "%.1f", s}' "$tmp/stdout")")
      fi
    else
      status=failed
      err=$(grep -v '^Command exited' "$tmp/stderr" | head -1 | tr ',"' ';'"'" | cut -c1-160)
      break
    fi
  done
  local med="" lo="" hi="" rmed="" rmax="" smed="" cov=""
  if [ $status = ok ]; then
    med=$(printf '%s\n' "${walls[@]}" | median)
    lo=$(printf '%s\n' "${walls[@]}" | sort -g | head -1)
    hi=$(printf '%s\n' "${walls[@]}" | sort -g | tail -1)
    rmed=$(printf '%s\n' "${rss[@]}" | median | awk '{printf "%.1f", $1 / 1024}')
    rmax=$(printf '%s\n' "${rss[@]}" | sort -g | tail -1 | awk '{printf "%.1f", $1 / 1024}')
    [ ${#stage[@]} -gt 0 ] && smed=$(printf '%s\n' "${stage[@]}" | median)
    # (a PNG of fluidsurf's has its background drawn: no coverage read from it)
    [ -s "$img" ] && { [[ $img == *.exr ]] || [ "$method" = vdb_tool ]; } && cov=$(coverage "$img")
    if [ -z "$RENDERER" ] && [[ $img == *.exr ]]; then
      local r; r=$(exr_attr "$img" gl_renderer); [ "$r" = CPU ] || RENDERER=$r
    fi
  fi
  echo "$set,$n,$method,$w,$h,$NRUNS,${#walls[@]},$med,$lo,$hi,$rmed,$rmax,$smed,$cov,$status,\"$err\"" >> "$CSV.new"
  log "$(printf '%-20s %9s  %-24s %4sx%-4s  %8s s  %8s MiB  cov %-6s %s %s' "$set" "$n" "$method" "$w" "$h" \
    "${med:--}" "${rmed:--}" "${cov:--}" "$status" "$err")"
}

# write_csv: the provenance header and the rows so far (after every set, so a
# run cut short leaves a valid CSV of the sets it finished)
write_csv() {
  {
    echo "# fluidsurf speed benchmark (experiments/bench/speed.sh$([ $QUICK = 1 ] && echo ' --quick')); $PROV; $(date -u +%Y-%m-%dT%H:%MZ)"
    echo "# baseline: reference@$BASE_COMMIT = $BASE_DESC"
    echo "# renderer of the GL methods: ${RENDERER:-unknown}; CPU methods: CPU; threads: $(nproc) cores, OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset}, LP_NUM_THREADS=${LP_NUM_THREADS:-unset}"
    echo "# machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "# vdb_tool: $(dpkg-query -W -f '${Package} ${Version}' libopenvdb-tools 2>/dev/null || echo unknown) (-points2ls voxel=r/2 radius=4 width=3 -render aperture=100 tan(fov/2), the camera below)"
    echo "# medians of $RUNS whole-process runs (box_10m: ${RUNS_10M:-$RUNS}) (/usr/bin/time: wall s, peak RSS); camera: the one fluidsurf $(git rev-parse --short HEAD) frames automatically, written into each set's scene"
    echo "# run time of the benchmark: $(($(date +%s) - T0)) s${1:+; $1}"
    cat "$CSV.new"
  } > "$CSV.tmp" && mv "$CSV.tmp" "$CSV"
}

echo "set,particles,method,width,height,runs,ok_runs,wall_s_median,wall_s_min,wall_s_max,peak_rss_mib_median,peak_rss_mib_max,stage_ms_median,coverage,status,error" > "$CSV.new"
in_list() { local x=$1; shift; for y in $@; do [ "$x" = "$y" ] && return 0; done; return 1; }
for i in "${!SET_NAMES[@]}"; do
  name=${SET_NAMES[$i]}
  [ -z "${SETS:-}" ] || in_list "$name" $SETS || continue
  log "set $name: preparing (camera, PLY for vdb_tool)"
  [ "${SET_KIND[$i]}" != file ] || [ -f "${SET_SRC[$i]}" ] ||
    { echo "speed.sh: ${SET_SRC[$i]} missing (the splash frame: experiments/bench/make_splash.sh; the DualSPHysics frame: set SHARED)" >&2; exit 1; }
  prepare_set "$i"
  scene=$WORK/$name.json
  NRUNS=$RUNS; [ "$name" != box_10m ] || NRUNS=${RUNS_10M:-$RUNS}
  im=$WORK/$name
  fs() { echo "$BIN" render "$scene" -q --timings -W "$SIZE" -H "$SIZE"; }
  bench "$name" "$P_N" reference "$SIZE" "$SIZE" "$im.reference.exr" $(fs) --method reference -o "$im.reference.exr"
  bench "$name" "$P_N" "reference thickness=off" "$SIZE" "$SIZE" "$im.reference_nothick.exr" \
    $(fs) --method reference --set reference.thickness=off -o "$im.reference_nothick.exr"
  bench "$name" "$P_N" spheres "$SIZE" "$SIZE" "$im.spheres.exr" $(fs) --method spheres -o "$im.spheres.exr"
  bench "$name" "$P_N" raycast_pca "$SIZE" "$SIZE" "$im.raycast_pca.exr" $(fs) --method raycast_pca -o "$im.raycast_pca.exr"
  in_list "$name" $LEVELSET_SETS &&
    bench "$name" "$P_N" "levelset thickness=off" "$SIZE" "$SIZE" "$im.levelset.exr" $(fs) --method levelset \
      --set levelset.thickness=off -o "$im.levelset.exr"
  voxel=$(awk -v r="$P_R" 'BEGIN {printf "%.9g", r / 2}')
  aperture=$(vdb_aperture "$FOV")
  bench "$name" "$P_N" vdb_tool "$SIZE" "$SIZE" "$im.vdb_tool.png" "$VDB_TOOL" -read "$CACHE/sets/$name.ply" \
    -points2ls voxel="$voxel" radius=4 width=3 \
    -render image="${SIZE}x$SIZE" translate="($P_EYE)" target="($P_TGT)" up="($P_UP)" aperture="$aperture" "$im.vdb_tool.png"
  if in_list "$name" $BASE_SETS; then
    bench "$name" "$P_N" "reference@$BASE_COMMIT" "$SIZE" "$SIZE" "$im.reference_base.exr" \
      "$BASE_BIN" render "$scene" -q --timings -W "$SIZE" -H "$SIZE" --method reference -o "$im.reference_base.exr"
  fi
  if [ "$name" = dam_break_7k ]; then # the fixed cost on a small frame, to an EXR and to a PNG
    bench "$name" "$P_N" reference 8 8 "$im.reference_8.exr" "$BIN" render "$scene" -q --timings -W 8 -H 8 \
      --method reference -o "$im.reference_8.exr"
    bench "$name" "$P_N" "reference to PNG" 8 8 "$im.reference_8.png" "$BIN" render "$scene" -q --timings -W 8 -H 8 \
      --method reference -o "$im.reference_8.png"
  fi
  if [ "$name" = splash ]; then # the fixed cost: start-up, load, grid, at 8x8 pixels
    bench "$name" "$P_N" reference 8 8 "$im.reference_8.exr" "$BIN" render "$scene" -q --timings -W 8 -H 8 \
      --method reference -o "$im.reference_8.exr"
    in_list "$name" $BASE_SETS && bench "$name" "$P_N" "reference@$BASE_COMMIT" 8 8 "$im.reference_base_8.exr" \
      "$BASE_BIN" render "$scene" -q --timings -W 8 -H 8 --method reference -o "$im.reference_base_8.exr"
  fi
  write_csv "in progress: $name was the last set finished"
done
write_csv
rm -f "$CSV.new"
log "wrote $CSV"
bash experiments/bench/speed_report.sh "$CSV" "$GROWTH" "$WORK"
log "done in $(($(date +%s) - T0)) s"
