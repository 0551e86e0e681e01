#!/usr/bin/env bash
# A fluidsurf compare study on Slurm: one job array of N shards and a merge job.
#
#   submit.sh SCENE.json -o DIR --shards N [--gpu] [--bin FLUIDSURF] [--dry-run]
#             [compare options ...] [-- sbatch options ...]
#   submit.sh --resume DIR [--dry-run] [-- sbatch options ...]
#
# Sbatch options after -- go to both jobs; with --resume they replace the ones the
# study was submitted with (which are kept in DIR/study.env otherwise).
# The array runs compare.sbatch (task K: compare ... --shard K/N -o DIR/shards/K);
# the merge job (merge.sbatch) depends on it with afterok and --kill-on-invalid-dep=yes,
# so a failed shard cancels the merge instead of leaving it pending. DIR then holds
# what 'fluidsurf compare SCENE [compare options] -o DIR' writes. --gpu asks each
# shard for a GPU (--gres=gpu:1) and renders through EGL (--gl egl). --resume
# re-submits only the shards without a DONE marker, with a new merge job.
# Prints "array JOBID" and "merge JOBID". Logs go to DIR/logs/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
die() { echo "submit.sh: $*" >&2; exit 2; }

scene="" dir="" shards="" gpu=0 bin="" dry=0 resume="" compare_args=() sbatch_args=()
while [ $# -gt 0 ]; do
  case $1 in
    -o) [ $# -ge 2 ] || die "-o needs a folder"; dir=$2; shift 2 ;;
    --shards) [ $# -ge 2 ] || die "--shards needs a count"; shards=$2; shift 2 ;;
    --gpu) gpu=1; shift ;;
    --bin) [ $# -ge 2 ] || die "--bin needs a path"; bin=$2; shift 2 ;;
    --dry-run) dry=1; shift ;;
    --resume) [ $# -ge 2 ] || die "--resume needs the study folder"; resume=$2; shift 2 ;;
    --) shift; sbatch_args=("$@"); break ;;
    *) if [ -z "$scene" ] && [ -z "$resume" ] && [ "${1#-}" = "$1" ]; then scene=$1; else compare_args+=("$1"); fi; shift ;;
  esac
done

# sbatch, or under --dry-run the command line it would run (with a made-up job id).
submit() {
  if [ $dry -eq 1 ]; then echo "sbatch $*" >&2; echo "$((RANDOM + 1000))"; return; fi
  sbatch --parsable "$@" | cut -d';' -f1
}

# The array over the shard indices $1 ("1-4" or "2,3") and its merge job.
submit_study() {
  local array=$1 gres=() id mid
  [ "$FS_GPU" -eq 1 ] && gres=(--gres=gpu:1)
  [ $dry -eq 1 ] || mkdir -p "$FS_DIR/logs" "$FS_DIR/shards"
  id=$(submit --array="$array" "${gres[@]}" --output="$FS_DIR/logs/shard-%a-%A.out" \
       "${FS_SBATCH[@]}" "$here/compare.sbatch" "$FS_DIR") || die "sbatch refused the shard array"
  mid=$(submit --dependency=afterok:"$id" --kill-on-invalid-dep=yes --output="$FS_DIR/logs/merge-%j.out" \
        "${FS_SBATCH[@]}" "$here/merge.sbatch" "$FS_DIR") || die "sbatch refused the merge job (array $id is queued)"
  [ $dry -eq 1 ] || echo "$id $mid" >> "$FS_DIR/jobs.txt"
  echo "array $id"
  echo "merge $mid"
}

if [ -n "$resume" ]; then
  [ -f "$resume/study.env" ] || die "$resume: not a study folder of submit.sh (no study.env)"
  # shellcheck source=/dev/null
  source "$resume/study.env"
  [ ${#sbatch_args[@]} -eq 0 ] || FS_SBATCH=("${sbatch_args[@]}")
  if [ $dry -eq 0 ] && [ -f "$FS_DIR/jobs.txt" ]; then
    live=$(squeue -h -o %i -j "$(tr ' \n' ',,' < "$FS_DIR/jobs.txt" | sed 's/,*$//')" 2>/dev/null || true)
    [ -z "$live" ] || die "$resume: jobs of this study are still queued or running ($(echo $live | tr ' ' ,)); wait or scancel them"
  fi
  todo=()
  for k in $(seq 1 "$FS_SHARDS"); do [ -f "$FS_DIR/shards/$k/DONE" ] || todo+=("$k"); done
  if [ ${#todo[@]} -eq 0 ]; then
    [ -f "$FS_DIR/metrics.csv" ] && { echo "submit.sh: $resume: every shard and the merge are done"; exit 0; }
    mid=$(submit --output="$FS_DIR/logs/merge-%j.out" "${FS_SBATCH[@]}" "$here/merge.sbatch" "$FS_DIR") || die "sbatch refused the merge job"
    echo "merge $mid"
    exit 0
  fi
  echo "submit.sh: re-submitting shard(s) ${todo[*]} of $FS_SHARDS" >&2
  submit_study "$(IFS=,; echo "${todo[*]}")"
  exit 0
fi

[ -n "$scene" ] || die "no scene given (submit.sh SCENE.json -o DIR --shards N)"
[ -f "$scene" ] || die "$scene: no such scene file"
[ -n "$dir" ] || die "no study folder given (-o DIR)"
[[ "$shards" =~ ^[0-9]+$ ]] && [ "$shards" -ge 1 ] && [ "$shards" -le 1024 ] || die "--shards ${shards:-?}: expected a count from 1 to 1024"
if [ -z "$bin" ]; then
  bin=$(command -v fluidsurf || true)
  [ -n "$bin" ] || bin=$here/../../build/fluidsurf
fi
[ -x "$bin" ] || die "$bin: no fluidsurf binary (build it, or pass --bin)"
[ ! -e "$dir/study.env" ] || die "$dir: already holds a study; use --resume $dir, or another folder"
[ $gpu -eq 0 ] || compare_args+=(--gl egl)
FS_CWD=$(pwd) FS_SHARDS=$shards FS_GPU=$gpu
FS_BIN=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
FS_SCENE=$scene FS_ARGS=("${compare_args[@]}") FS_SBATCH=("${sbatch_args[@]}")
if [ $dry -eq 1 ]; then  # show the commands, make nothing
  FS_DIR=$(realpath -m "$dir")
  echo "shard K: $FS_BIN compare $FS_SCENE ${FS_ARGS[*]} --shard K/$shards --resume -o $FS_DIR/shards/K" >&2
  submit_study "1-$shards"
  exit 0
fi
mkdir -p "$dir" 2>/dev/null || die "$dir: cannot create the study folder"
[ -w "$dir" ] || die "$dir: study folder is not writable"
FS_DIR=$(cd "$dir" && pwd)
# Everything a shard, the merge and --resume need, paths absolute, written once.
{
  echo "# fluidsurf study of submit.sh, $(date -u +%FT%TZ)"
  declare -p FS_DIR FS_CWD FS_SHARDS FS_GPU FS_BIN FS_SCENE FS_ARGS FS_SBATCH
} > "$FS_DIR/study.env.tmp" && mv "$FS_DIR/study.env.tmp" "$FS_DIR/study.env"
submit_study "1-$shards"
