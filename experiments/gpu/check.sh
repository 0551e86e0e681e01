#!/usr/bin/env bash
# A short check of a GPU node in one device call (about a minute, after the machine's
# start): the driver's value of every GL limit fluidsurf relies on (render_bench
# --limits, docs/DESIGN.md "GL limits"), and every shader variant compiled and run by the
# vendor's driver, with a software renderer refused (FLUIDSURF_REQUIRE_GPU=1): compare of
# every method on the bundled dam break, plain and with --counters (the counting
# variants), and the GPU simulator. FS_SHADER_DUMP records what each run compiled.
# Writes into OUT: limits.csv, compiled.csv (run, stage file, defines), check.log, and
# metrics.csv / counters.csv of the two compares.
# usage: experiments/gpu/check.sh [--quick] [--bin DIR] [-o OUT]   (default DIR .gpu/pack, OUT $OUT or out/check)
# DIR: a scripts/pack_lean.sh folder or a build folder (its tools under experiments/).
# --quick: the same runs at small sizes (run.sh --quick, the ctest gpu_quick, on llvmpipe).
# run.sh runs it as its step "check" (into its folder's check/).
# Exit status: 0 when every step passed, 1 otherwise (check.log says which).
set -uo pipefail
bin="" out=${OUT:-} size=256 sim=20000
while [ $# -gt 0 ]; do
  case $1 in
    --quick) size=64 sim=2000 ;;
    --bin|-o) [ $# -ge 2 ] || { echo "check.sh: $1 needs a folder" >&2; exit 2; }
              if [ "$1" = -o ]; then out=$2; else bin=$2; fi; shift ;;
    *) echo "check.sh: unknown argument $1 (usage: check.sh [--quick] [--bin DIR] [-o OUT])" >&2; exit 2 ;;
  esac
  shift
done
# a folder given is the caller's; the defaults are the repository's
[ -n "$bin" ] && bin=$(realpath -m "$bin")
[ -n "$out" ] && out=$(realpath -m "$out")
cd "$(dirname "$0")/../.."
bin=${bin:-$PWD/.gpu/pack} out=${out:-$PWD/out/check}
mkdir -p "$out"
export FLUIDSURF_GL=${FLUIDSURF_GL:-egl} FLUIDSURF_REQUIRE_GPU=${FLUIDSURF_REQUIRE_GPU:-1}
source experiments/gpu/node_env.sh
node_gl_env
node_unpack_loaders
tool() { # the path of a program in the pack folder or in a build folder's experiments/
  for p in "$bin/$1" "$bin/experiments/$1"; do [ -x "$p" ] && { echo "$p"; return; }; done
  echo "check.sh: $1 not found in $bin" >&2; exit 2
}
FS=$(tool fluidsurf) || exit 2
RB=$(tool render_bench) || exit 2
if [ -f "$bin/provenance" ]; then prov=$(cat "$bin/provenance")
else source experiments/lib.sh; prov=$(study_commit); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
step() { # step NAME CMD...: runs CMD, logs its exit status and last stderr line
  local name=$1; shift
  mkdir -p "$work/dump/$name"
  FS_SHADER_DUMP=$work/dump/$name "$@" > "$work/$name.out" 2> "$work/$name.err"
  local rc=$?
  echo "$name: exit $rc $(tail -1 "$work/$name.err")" | tee -a "$out/check.log"
  [ $rc = 0 ] || fails=$((fails + 1))
}
: > "$out/check.log"
step limits "$RB" --limits
{ echo "# experiments/gpu/check.sh; $prov; $("$RB" --probe 2> /dev/null | tr '\n' ';')"
  cat "$work/limits.out"; } > "$out/limits.csv"
scene=experiments/scenes/dam_break_ply.json
step compare "$FS" compare "$scene" -W "$size" -H "$size" -q --no-cache -o "$work/compare"
step counters "$FS" compare "$scene" -W "$size" -H "$size" -q --no-cache --counters -o "$work/counters"
step simulate "$FS" simulate dam_break --gpu --particles "$sim" --frames 2 -q -o "$work/sim_%04d.ply"
cp "$work/compare/metrics.csv" "$out/metrics.csv" 2> /dev/null
cp "$work/counters/counters.csv" "$out/counters.csv" 2> /dev/null
{ echo "# experiments/gpu/check.sh; $prov"; echo "run,stage,defines"
  for d in "$work"/dump/*/; do
    [ -f "$d/index.tsv" ] && awk -F'\t' -v r="$(basename "$d")" '{print r "," $1 ",\"" $2 "\""}' "$d/index.tsv" | sort -u
  done; } > "$out/compiled.csv"
echo "check.sh: $(($(grep -c . "$out/compiled.csv") - 2)) stage variants compiled by the driver; $fails failed steps" |
  tee -a "$out/check.log"
[ $fails = 0 ]
