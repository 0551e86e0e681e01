#!/usr/bin/env bash
# Wall time of a sharded study through Slurm: tests/slurm_cluster.sh's study (6 frames,
# spheres + aniso_ssf + the reference, 48x48) and a larger one (12 frames, 256x256),
# each as 1 process, as 1 shard and as 4 shards on a one-node localhost cluster
# (local_cluster.sh), from submit.sh to the merge job's end. Medians of REPEATS runs.
# Writes results/slurm/scaling.csv and the table of results/slurm/README.md (not the root
# README.md: a tracked file outside results/ would mark every later study dirty=1).
#   bash experiments/slurm/scaling.sh [BIN] [REPEATS]    (as root, from the repository root)
# FS_QUICK=1 (run_all.sh --quick): the test study only, one run, into out/quick/results/slurm,
# and no table change.
set -euo pipefail
cd "$(dirname "$0")/../.."
src=$(pwd)
source experiments/lib.sh
BIN=$(realpath "${1:-${BIN:-build/fluidsurf}}") REPEATS=${2:-$(quick 3 1)}
source experiments/slurm/local_cluster.sh
out=$(realpath -m "$RESULTS/slurm") # absolute: the runs below work in $work
work=$(mktemp -d /tmp/fluidsurf-scaling.XXXXXX)
trap 'cluster_stop; rm -rf "$work"' EXIT
mkdir -p "$out"
cluster_start "$work/cluster"
cd "$work"
printf '{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 5, "moving": true}, "radius": 0.025}' > test.json
printf '{"particles": {"synthetic": "slab", "size": [24, 6, 24], "first": 0, "last": 11, "moving": true}, "radius": 0.025}' > large.json
now() { date +%s.%N; }

# one_run STUDY SIZE SHARDS: seconds from submission to the merged study (SHARDS=0: one process)
one_run() {
  local scene=$1.json size=$2 shards=$3 d="$work/$1-$3-$RANDOM" t0 aid mid
  local args=(--methods spheres,aniso_ssf --reference reference -W "$size" -H "$size" --repeat 1 -q --no-cache)
  t0=$(now)
  if [ "$shards" -eq 0 ]; then
    "$BIN" compare "$scene" "${args[@]}" -o "$d"
  else
    bash "$src/experiments/slurm/submit.sh" "$scene" -o "$d" "${args[@]}" --shards "$shards" --bin "$BIN" > "$d.ids"
    aid=$(awk '$1 == "array" {print $2}' "$d.ids") mid=$(awk '$1 == "merge" {print $2}' "$d.ids")
    wait_jobs 900 "$aid" "$mid" || { echo "scaling: $1 with $shards shards did not finish" >&2; exit 1; }
    [ "$(job_state "$mid")" = COMPLETED ] || { echo "scaling: merge job $mid ended $(job_state "$mid")" >&2; exit 1; }
  fi
  awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.2f\n", b - a}'
}

commit=$(cd "$src" && study_commit)
csv=$out/scaling.csv
{
  echo "study,frames,size,mode,shards,wall_s_median,wall_s_min,wall_s_max"
} > "$work/rows"
specs=("test 6 48")
[ "$FS_QUICK" = 1 ] || specs+=("large 12 256")
for spec in "${specs[@]}"; do
  read -r study frames size <<< "$spec"
  for shards in 0 1 4; do
    times=()
    for _ in $(seq "$REPEATS"); do times+=("$(one_run "$study" "$size" "$shards")"); done
    mode=slurm; [ "$shards" -eq 0 ] && mode=process
    printf '%s\n' "${times[@]}" > t
    echo "$study,$frames,$size,$mode,$([ "$shards" -eq 0 ] && echo 1 || echo "$shards"),$(median < t),$(sort -g t | head -1),$(sort -g t | tail -1)" >> "$work/rows"
  done
done
renderer=$(grep -ho 'gl_renderer=[^;]*' "$work"/test-0-*/metrics.csv | head -1)
{ echo "# $commit; host_cpus=$(nproc); repeats=$REPEATS; one node; $renderer"; cat "$work/rows"; } > "$csv.tmp"
publish "$csv"
cd "$src"
if [ "$FS_QUICK" = 1 ]; then echo "scaling: wrote $csv"; exit 0; fi
python3 experiments/tools/csv_table.py "$csv" results/slurm/README.md
echo "scaling: wrote $csv and the table of results/slurm/README.md"
