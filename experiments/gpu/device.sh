#!/usr/bin/env bash
# The whole command of one GPU-machine call (experiments/gpu/README.md): on a bare node
# with only the NVIDIA driver, unpack the GL loaders carried as Debian packages (.gl/,
# when there), run experiments/gpu/run.sh from the lean pack (.gpu/pack) on EGL, and
# write into OUT: gpu.tar.gz (the run's folder: env.csv, status.csv, the CSVs, logs,
# the demo's images, README.md and tables.csv from report.py), and beside it README.md, status.csv and run.log to read
# at once. A call returns at most 8 files, so the folder travels as one archive.
#
# usage: experiments/gpu/device.sh [--quick] [-o OUT] [--steps LIST]   (default OUT: $OUT, else out/device)
# --steps goes to run.sh: the study takes two calls, the first --steps xiao2017_table1, the
# second the other steps; experiments/gpu/merge.sh joins them (experiments/gpu/README.md).
# Rehearse it here with --quick (EGL on llvmpipe). BUDGET_S (default 290) caps run.sh, so
# the call, start included, fits in 6 minutes. Exit status: run.sh's.
set -uo pipefail
quick=() steps=() out=${OUT:-}
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=(--quick) ;;
    -o) [ $# -ge 2 ] || { echo "device.sh: -o needs a folder" >&2; exit 2; }; out=$2; shift ;;
    --steps) [ $# -ge 2 ] || { echo "device.sh: --steps needs a list" >&2; exit 2; }; steps=(--steps "$2"); shift ;;
    *) echo "device.sh: unknown argument $1 (usage: device.sh [--quick] [-o OUT] [--steps LIST])" >&2; exit 2 ;;
  esac
  shift
done
out=$(realpath -m "${out:-out/device}")
cd "$(dirname "$0")/../.."
[ -x .gpu/pack/fluidsurf ] || { echo "device.sh: .gpu/pack/fluidsurf missing (bash scripts/pack_lean.sh --gl .gpu/pack)" >&2; exit 2; }
mkdir -p "$out"
source experiments/gpu/node_env.sh
node_unpack_loaders
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export FLUIDSURF_GL=egl BUDGET_S=${BUDGET_S:-290}
bash experiments/gpu/run.sh "${quick[@]}" "${steps[@]}" --bin .gpu/pack -o "$work/gpu" 2>&1 | tee "$out/run.log"
rc=${PIPESTATUS[0]}
# the README only when report.py succeeds (a failure is in run.log, and no empty README travels)
if python3 experiments/gpu/report.py "$work/gpu" > "$work/README.tmp" 2>> "$out/run.log" &&
  python3 experiments/gpu/report.py --tables "$work/gpu" > "$work/tables.tmp" 2>> "$out/run.log"; then
  mv "$work/tables.tmp" "$work/gpu/tables.csv"
  mv "$work/README.tmp" "$work/gpu/README.md" && cp "$work/gpu/README.md" "$out/"
else
  echo "device.sh: report.py failed (run.log)" | tee -a "$out/run.log" >&2
fi
# the bounds the run must meet (issue 52: the march on both volumes of inacio2010's Table I), in run.log
python3 experiments/gpu/report.py --bounds "$work/gpu" 2>&1 | tee -a "$out/run.log"
[ -f "$work/gpu/status.csv" ] && cp "$work/gpu/status.csv" "$out/"
tar -czf "$out/gpu.tar.gz" -C "$work" gpu
cat "$work/gpu/README.md" 2> /dev/null
echo "device.sh: run.sh exit $rc; $(du -b "$out/gpu.tar.gz" | cut -f1) bytes in $out/gpu.tar.gz"
exit "$rc"
