#!/usr/bin/env bash
# The papers' speed tables on one GPU, in one prepared run (docs/DESIGN.md, "Timing"),
# budgeted to BUDGET_S seconds (default 290: with the start, one device call of at most
# 6 minutes, so a lease of 15 minutes has room for a second try):
#   xiao2017 Table 1   raycast_pca on synthetic boxes of about the paper's particle
#                      counts (0.78M .. 142.6M) at 512^2 .. 1920^2, its sprite passes on
#                      the compute splatter (splat=compute) and on the raster (the paper's)
#   xu2022 Fig. 9      aniso_ssf, 5 filters x anisotropy off/on, against particle count;
#                      the narrow-range filter also with splat=compute, anisotropy off/on
#   inacio2010 I, II   SPH dam break, CPU path against GPU path; volume ray casting
#                      against spheres (experiments/tools/inacio_tables)
#   iwasaki2006 4      the 256^3 density grid of about 210k particles: slice splatting
#                      on the GL against the exact CPU sum (experiments/tools/density_bench)
#   demo               `fluidsurf compare` of the bundled dam break at 1024^2, and of the
#                      sprite-splatting methods with splat=compute (demo_splat_*.csv)
#   repeat             the xiao2017 cells at 1024^2 and the demo again, into DIR/repeat/,
#                      for the run-to-run spread (report.py's repeatability section)
#   check              experiments/gpu/check.sh into DIR/check/: the GL limits as a CSV,
#                      every shader variant compiled by the driver
# Every timed cell keeps one small image of what it timed in DIR/images/ (at most 256
# pixels a side; render_bench's at the cell's smallest size, inacio_tables' last frame
# of each table); the density grid step renders no image.
# Every row holds the wall time between glFinish calls and the GL clock's time of the
# stage (gpu_ms), GL_RENDERER and GL_VERSION. The large particle sets are generated
# where the script runs (synthetic boxes, the simulator): nothing big is carried.
#
# Every CSV starts with a provenance line, "# commit=...; dirty=0|1": read from
# BINDIR/provenance (scripts/pack_lean.sh records it where the pack is made, since a
# copy of the repository on a GPU node has no .git), else from this repository.
#
# Usage: experiments/gpu/run.sh [--quick] [-o DIR] [--bin DIR] [--steps LIST]
#   --quick  the same steps at small sizes, for llvmpipe (the ctest gpu_quick; budget 300 s)
#   -o DIR   output folder (default out/gpu, out/gpu-quick with --quick); it holds
#            env.csv, status.csv and one CSV per step
#   --bin    folder with fluidsurf, render_bench, inacio_tables, density_bench: a
#            scripts/pack_lean.sh folder, or a build folder (default build-lean)
#   --steps  the steps to run, comma-separated, of xiao2017_table1, xu2022_fig9,
#            inacio2010_tables, iwasaki2006_density_grid, demo_compare, repeat, check
#            (default all): the whole study does not fit one device call, so a first
#            call runs xiao2017_table1 and a second the rest, each into its own DIR
#            (experiments/gpu/README.md; experiments/gpu/merge.sh joins the two)
# FLUIDSURF_GL picks the context (default egl). BUDGET_S (default 290, quick 300)
# caps the whole run: a cell that would start after the budget is spent is written
# to status.csv as skipped, so a lease of about 15 minutes has room for a retry.
# Each step but the last has a share of it (SHARE_* seconds), so one slow step cannot
# starve the others; xiao2017's Table 1 comes last and has what is left.
# Exit status: 0 when every cell finished, 1 when one failed or was cut or skipped
# (status.csv says which; the rows of the others are written all the same), 2 bad usage.
set -uo pipefail
usage() { echo "run.sh: $1 (usage: run.sh [--quick] [-o DIR] [--bin DIR] [--steps LIST])" >&2; exit 2; }
QUICK=0 OUTDIR="" BINDIR="" STEPS=xiao2017_table1,xu2022_fig9,inacio2010_tables,iwasaki2006_density_grid,demo_compare,repeat,check
ALL_STEPS=$STEPS
while [ $# -gt 0 ]; do
  case $1 in
    --quick) QUICK=1 ;;
    --steps) [ $# -ge 2 ] || usage "--steps needs a list"
             for s in ${2//,/ }; do [[ ",$ALL_STEPS," == *",$s,"* ]] || usage "unknown step $s"; done
             STEPS=$2; shift ;;
    -o|--bin) [ $# -ge 2 ] || usage "$1 needs a folder"
              if [ "$1" = -o ]; then OUTDIR=$(realpath -m "$2"); else BINDIR=$(realpath -m "$2"); fi; shift ;;
    *) usage "unknown argument $1" ;;
  esac
  shift
done
cd "$(dirname "$0")/../.." # relative -o and --bin were resolved against the caller's folder
[ -n "$BINDIR" ] || BINDIR=build-lean
[ -n "$OUTDIR" ] || OUTDIR=out/gpu$([ $QUICK = 1 ] && echo -quick)
export FLUIDSURF_GL=${FLUIDSURF_GL:-egl}
# a timing run refuses a software renderer (fluidsurf --require-gpu), so it never times llvmpipe
# by mistake; --quick runs on llvmpipe; FLUIDSURF_REQUIRE_GPU=0 lets a full run check itself there
[ $QUICK = 1 ] || export FLUIDSURF_REQUIRE_GPU=${FLUIDSURF_REQUIRE_GPU:-1}
source experiments/gpu/node_env.sh
node_gl_env

tool() { # the path of a program in BINDIR (pack folder) or BINDIR/experiments (build folder)
  for p in "$BINDIR/$1" "$BINDIR/experiments/$1"; do [ -x "$p" ] && { echo "$p"; return; }; done
  echo "run.sh: $1 not found in $BINDIR (build it: bash scripts/build_lean.sh)" >&2; exit 2
}
FS=$(tool fluidsurf) RB=$(tool render_bench) IT=$(tool inacio_tables) DB=$(tool density_bench)
[ -n "$FS" ] && [ -n "$RB" ] && [ -n "$IT" ] && [ -n "$DB" ] || exit 2

if [ $QUICK = 1 ]; then
  BUDGET_S=${BUDGET_S:-300}
  T1_SIDES="16 24" T1_SIZES="128,192" T1_RUNS=1
  F9_SIDES="16" F9_SIZE=96 F9_RUNS=1
  IN_COUNTS="1024" IN_SETTLE=1 IN_FRAMES=3 IN_SIZE=64 IN_GRID=32 IN_LIMIT=30
  DG_SCENE=experiments/scenes/dam_break_ply.json DG_RES="64" DG_RUNS=1 DG_ONE=64
  DEMO_SIZE=128 DEMO_RUNS=1 RP_SIZE=192
  SHARE_F9=${SHARE_F9:-30} SHARE_IN=${SHARE_IN:-30} SHARE_DG=${SHARE_DG:-15} SHARE_DEMO=${SHARE_DEMO:-40}
  SHARE_RP=${SHARE_RP:-40} SHARE_CK=${SHARE_CK:-90}
else
  BUDGET_S=${BUDGET_S:-290}
  # cube sides whose cubes come nearest xiao2017's sets: 779,752 2,027,776 12,394,215 37,975,520 142,612,764
  T1_SIDES="92 127 231 336 522" T1_SIZES="512,768,1024,1440,1920" T1_RUNS=3
  F9_SIDES="46 67 100 144" F9_SIZE=1024 F9_RUNS=3
  IN_COUNTS="1024 2048 4096 8192 32768 131072" IN_SETTLE=2 IN_FRAMES=3 IN_SIZE=512 IN_GRID=128 IN_LIMIT=20
  DG_SCENE=experiments/scenes/box_200k.json DG_RES="128 256" DG_RUNS=3 DG_ONE=256
  DEMO_SIZE=1024 DEMO_RUNS=3 RP_SIZE=1024
  SHARE_F9=${SHARE_F9:-40} SHARE_IN=${SHARE_IN:-40} SHARE_DG=${SHARE_DG:-45} SHARE_DEMO=${SHARE_DEMO:-30}
  SHARE_RP=${SHARE_RP:-70} SHARE_CK=${SHARE_CK:-60}
fi
mkdir -p "$OUTDIR/images"
if [ -f "$BINDIR/provenance" ]; then PROV=$(cat "$BINDIR/provenance")
else source experiments/lib.sh; PROV=$(study_commit); fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
START=$(date +%s) FAILED=0 STEP_END=""
left() { # seconds left: of the whole budget, and of the current step's share
  local now l s; now=$(date +%s); l=$((BUDGET_S - (now - START)))
  [ -n "$STEP_END" ] && s=$((STEP_END - now)) && [ "$s" -lt "$l" ] && l=$s
  echo "$l"
}
step_share() { STEP_END=$(($(date +%s) + $1)); } # the next cells' share, in seconds; "" lifts it
want() { [[ ",$STEPS," == *",$1,"* ]]; } # want STEP: STEP is among --steps


# status.csv: one row per cell: what ran, how long, how it ended
printf '# experiments/gpu/run.sh; %s\nstep,cell,seconds,exit,note\n' "$PROV" > "$OUTDIR/status.csv"
# cell STEP NAME LIMIT CMD...: runs CMD (stdout appended to STEP's raw file) under
# min(LIMIT, budget left); skipped when the budget is spent
cell() {
  local step=$1 name=$2 limit=$3; shift 3
  local l; l=$(left)
  if [ "$l" -le 5 ]; then
    echo "$step,$name,0,,skipped: the budget (${BUDGET_S} s, or this step's share) is spent" >> "$OUTDIR/status.csv"; FAILED=1; return
  fi
  [ "$limit" -gt "$l" ] && limit=$l
  local t0 rc=0 err=$TMP/cell.err; t0=$(date +%s)
  timeout "$limit" "$@" >> "$TMP/$step.raw" 2> "$err" || rc=$?
  cat "$err" >> "$TMP/$step.err"
  local note=""
  [ $rc = 124 ] && note="cut at ${limit} s: the rows finished before are kept"
  [ $rc != 0 ] && [ $rc != 124 ] && note="failed: $(tail -1 "$err" | tr ',' ';' | cut -c1-200)"
  [ $rc != 0 ] && FAILED=1
  echo "$step,$name,$(($(date +%s) - t0)),$rc,$note" >> "$OUTDIR/status.csv"
  printf '%-10s %-28s %4ss  exit %s %s\n' "$step" "$name" "$(($(date +%s) - t0))" "$rc" "$note"
}
# the environment of a timed cell's tool: keep a small image of what it timed, named PREFIX...
shots() { echo "RENDER_BENCH_PNG=$OUTDIR/images/$1 RENDER_BENCH_PNG_SIZE=$2 RENDER_BENCH_PNG_MAX=256 INACIO_TABLES_PNG=$OUTDIR/images/$1 INACIO_TABLES_PNG_MAX=256"; }
box_scene() { # box_scene SIDE: a synthetic lattice box of SIDE^3 particles (r = 0.025, jitter 0.1 r)
  local f=$TMP/box_$1.json
  printf '{"particles": {"synthetic": "box", "size": [%d, %d, %d], "jitter": 0.1, "seed": 1}, "radius": 0.025, "material": "water", "background": "checker"}\n' "$1" "$1" "$1" > "$f"
  echo "$f"
}

# ---- the machine and the context ----
{
  echo "# experiments/gpu/run.sh; $PROV"
  echo "key,value"
  echo "date,$(date -u +%FT%TZ)"
  echo "mode,$([ $QUICK = 1 ] && echo quick || echo full)"
  echo "fluidsurf,\"$("$FS" --version 2>/dev/null | head -1)\""
  echo "cpu,\"$(nproc) cores; $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')\""
  echo "context,$FLUIDSURF_GL"
  "$RB" --probe 2> "$TMP/probe.err" | awk 'NR == 1 {print "gl_renderer,\"" $0 "\""} NR == 2 {print "gl_version,\"" $0 "\""}'
  if command -v nvidia-smi > /dev/null; then # the GPU, its driver and its clocks (now and at most)
    nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm,clocks.mem,clocks.max.sm,clocks.max.mem,power.limit \
      --format=csv,noheader | head -1 | awk -F', ' '{printf "gpu,\"%s\"\ndriver,%s\ngpu_memory,%s\nclock_sm,%s\nclock_mem,%s\nclock_max_sm,%s\nclock_max_mem,%s\npower_limit,%s\n", $1, $2, $3, $4, $5, $6, $7, $8}'
  fi
} > "$OUTDIR/env.csv"
grep -q '^gl_renderer' "$OUTDIR/env.csv" || { echo "run.sh: no OpenGL context: $(cat "$TMP/probe.err")" >&2; exit 1; }
sed -n 's/^gl_renderer,//p; s/^gl_version,//p' "$OUTDIR/env.csv"

RB_HEAD="label,particles,method,variant,size,run,stage,ms,gpu_ms,renderer,gl_version"
# ---- xu2022 Fig. 9: aniso_ssf, each filter, anisotropy off and on; the sprite passes on
# the compute splatter too, with the default narrow-range filter only (the filter does not
# touch the sprite passes, so one filter answers how the splat paths compare) ----
variants=()
for a in off on; do for f in none gaussian bilateral curvature narrow; do
  variants+=("aniso_ssf.anisotropy=$a;aniso_ssf.filter=$f")
done; done
for a in off on; do variants+=("aniso_ssf.anisotropy=$a;aniso_ssf.filter=narrow;aniso_ssf.splat=compute"); done
if want xu2022_fig9; then
  step_share "$SHARE_F9"
  for side in $F9_SIDES; do
    cell xu2022_fig9 "box_${side}^3" 90 env $(shots "xu2022_box_$side" "$F9_SIZE") "$RB" "$(box_scene "$side")" \
      "box_$side" aniso_ssf "$F9_SIZE" "$F9_RUNS" "${variants[@]}"
  done
fi
# ---- inacio2010 Tables I and II: simulation and rendering, CPU path and GPU path ----
if want inacio2010_tables; then
  step_share "$SHARE_IN"
  for n in $IN_COUNTS; do for path in cpu gpu; do
    cell inacio2010_tables "${n}_$path" 60 env $(shots "inacio2010_${n}_$path" 0) "$IT" "$n" "$path" "$IN_SETTLE" \
      "$IN_FRAMES" "$IN_SIZE" "$IN_GRID" "$IN_LIMIT"
  done; done
fi
# ---- iwasaki2006 section 4: the density grid, slice splatting against the exact CPU sum ----
if want iwasaki2006_density_grid; then
  step_share "$SHARE_DG"
  for res in $DG_RES; do
    cell iwasaki2006_density_grid "res_$res" 60 "$DB" "$DG_SCENE" "$(basename "$DG_SCENE" .json)" "$res" "$DG_RUNS" 16
  done
  # the exact sum on one CPU thread too: the paper's 88x is against one core
  cell iwasaki2006_density_grid "res_${DG_ONE}_1thread" 60 env OMP_NUM_THREADS=1 "$DB" "$DG_SCENE" \
    "$(basename "$DG_SCENE" .json)_1thread" "$DG_ONE" 1 16
fi
# ---- the demo comparison; then the sprite-splatting methods with splat=compute ----
if want demo_compare; then
  step_share "$SHARE_DEMO"
  cell demo_compare "dam_break_${DEMO_SIZE}" 90 "$FS" compare --no-cache experiments/scenes/dam_break_ply.json \
    -W "$DEMO_SIZE" -H "$DEMO_SIZE" --repeat "$DEMO_RUNS" -q -o "$TMP/demo"
  cell demo_compare "dam_break_${DEMO_SIZE}_splat_compute" 90 "$FS" compare --no-cache \
    experiments/scenes/dam_break_ply.json --methods spheres,raycast_pca,aniso_ssf --set spheres.splat=compute \
    --set raycast_pca.splat=compute --set aniso_ssf.splat=compute -W "$DEMO_SIZE" -H "$DEMO_SIZE" \
    --repeat "$DEMO_RUNS" -q -o "$TMP/demo_splat"
fi

# ---- the repeat: the xiao2017 cells at one size and the demo again, for the run-to-run spread ----
if want repeat; then # the demo first, the largest box last, so a spent share cuts only the biggest cells
  step_share "$SHARE_RP"
  cell repeat "dam_break_${DEMO_SIZE}" 90 "$FS" compare --no-cache experiments/scenes/dam_break_ply.json \
    -W "$DEMO_SIZE" -H "$DEMO_SIZE" --repeat "$DEMO_RUNS" -q -o "$TMP/repeat_demo"
  : > "$TMP/repeat.raw" # render_bench's rows only
  for side in $T1_SIDES; do
    cell repeat "xiao2017_box_${side}^3_$RP_SIZE" 60 "$RB" "$(box_scene "$side")" "box_$side" raycast_pca "$RP_SIZE" \
      "$T1_RUNS" "raycast_pca.splat=compute" "raycast_pca.splat=raster"
  done
  mv "$TMP/repeat.raw" "$TMP/repeat_xiao.raw"
fi
# ---- the node's check: GL limits, every shader variant compiled by the driver (check.sh) ----
if want check; then
  step_share "$SHARE_CK"
  cell check gpu_check "$SHARE_CK" env FLUIDSURF_REQUIRE_GPU="${FLUIDSURF_REQUIRE_GPU:-0}" \
    bash experiments/gpu/check.sh $([ $QUICK = 1 ] && echo --quick) --bin "$BINDIR" -o "$OUTDIR/check"
fi

# ---- xiao2017 Table 1: raycast_pca, particle count x image size, the sprite passes on the
# compute splatter, then on the raster; last, largest set last, so a spent budget cuts only
# the biggest cells ----
if want xiao2017_table1; then
  STEP_END="" # the rest of the budget
  for side in $T1_SIDES; do
    cell xiao2017_table1 "box_${side}^3" 200 env $(shots "xiao2017_box_$side" "${T1_SIZES%%,*}") "$RB" \
      "$(box_scene "$side")" "box_$side" raycast_pca "$T1_SIZES" "$T1_RUNS" "raycast_pca.splat=compute" "raycast_pca.splat=raster"
  done
fi
# ---- the CSVs, each with its header and the GL version on every row ----
glv=$(sed -n 's/^gl_version,//p' "$OUTDIR/env.csv")
write() { # write STEP HEADER: the raw rows of STEP under HEADER
  [ -f "$TMP/$1.raw" ] || return 0
  { echo "# experiments/gpu/run.sh; $PROV"; echo "$2"; cat "$TMP/$1.raw"; } > "$OUTDIR/$1.csv"
}
write xiao2017_table1 "$RB_HEAD"
write xu2022_fig9 "$RB_HEAD"
write inacio2010_tables "particles_requested,particles,boundary,path,sim_renderer,gl_renderer,frame,t,steps,table,stage,ms,gpu_ms,gl_version"
write iwasaki2006_density_grid "label,particles,res,dims,method,run,ms,rel_l2_vs_exact,disks,renderer,threads,gpu_ms,gl_version"
demo_csvs() { # demo_csvs FOLDER PREFIX: FOLDER's timings.csv and metrics.csv as PREFIX_timings.csv, PREFIX_metrics.csv
  { echo "# experiments/gpu/run.sh; $PROV"; grep -v '^#' "$1/timings.csv" |
    awk -v v="$glv" 'NR == 1 {print $0 ",gl_version"; next} {print $0 "," v}'; } > "$OUTDIR/$2_timings.csv"
  local glr; glr=$(sed -n 's/^gl_renderer,//p' "$OUTDIR/env.csv") # the context the GL methods ran on
  { echo "# experiments/gpu/run.sh; $PROV"; grep -v '^#' "$1/metrics.csv" |
    awk -v r="$glr" -v v="$glv" 'NR == 1 {print $0 ",gl_renderer,gl_version"; next} {print $0 "," r "," v}'; } > "$OUTDIR/$2_metrics.csv"
}
[ -f "$TMP/demo_splat/timings.csv" ] && demo_csvs "$TMP/demo_splat" demo_splat
if [ -f "$TMP/repeat_xiao.raw" ] || [ -f "$TMP/repeat_demo/timings.csv" ]; then # repeat/: a run folder of its own
  mkdir -p "$OUTDIR/repeat"
  sed "s/^date,.*/date,$(date -u +%FT%TZ)/" "$OUTDIR/env.csv" > "$OUTDIR/repeat/env.csv"
  [ -f "$TMP/repeat_xiao.raw" ] && { echo "# experiments/gpu/run.sh; $PROV"; echo "$RB_HEAD"; cat "$TMP/repeat_xiao.raw"; } > "$OUTDIR/repeat/xiao2017_table1.csv"
  [ -f "$TMP/repeat_demo/timings.csv" ] && (OUTDIR=$OUTDIR/repeat && demo_csvs "$TMP/repeat_demo" demo)
fi
if [ -f "$TMP/demo/timings.csv" ]; then
  demo_csvs "$TMP/demo" demo
  mkdir -p "$OUTDIR/demo" && cp "$TMP"/demo/*.png "$OUTDIR/demo/" 2> /dev/null # to look at what the GPU drew
fi
# every step's stderr (a driver's shader log lands there)
mkdir -p "$OUTDIR/logs" && for e in "$TMP"/*.err; do [ -s "$e" ] && cp "$e" "$OUTDIR/logs/"; done
echo "run.sh: $(($(date +%s) - START)) s; wrote $OUTDIR: $(cd "$OUTDIR" && ls | tr '\n' ' ')"
[ $FAILED = 0 ] || { echo "run.sh: some cells did not finish: see $OUTDIR/status.csv" >&2; exit 1; }
