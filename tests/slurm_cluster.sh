#!/usr/bin/env bash
# A sharded compare study on a real one-node Slurm cluster (munged, slurmctld and
# slurmd of Debian's slurm-wlm, started here: experiments/slurm/local_cluster.sh):
# submit.sh's 4-shard array and merge job give the single process's metrics; a
# cancelled and a failed array task leave no DONE and cancel the merge; submit.sh --resume
# completes the study. Every daemon is stopped by pid on exit, failure included.
#   bash tests/slurm_cluster.sh [BIN SRC T]   (from the repository root: build/fluidsurf)
set -u
SRC=${2:-$(pwd)}
BIN=$(cd "$(dirname "${1:-build/fluidsurf}")" && pwd)/$(basename "${1:-build/fluidsurf}")
T=${3:-$SRC/build/test-out/slurm_cluster}
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
[ -x "$BIN" ] || { echo "FAIL no fluidsurf binary at $BIN"; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "FAIL slurmd must run as root to start jobs (this test starts its own cluster)"; exit 1; }
SUBMIT=$SRC/experiments/slurm/submit.sh
source "$SRC/experiments/slurm/local_cluster.sh"
trap cluster_stop EXIT
cd "$T" || exit 1
cluster_start "$T/cluster"; rc=$?
check '[ $rc -eq 0 ]' "munged, slurmctld and slurmd start"
[ $rc -eq 0 ] || { tail -n 5 "$T"/cluster/*.log; exit 1; }

# The study: six frames of a moving slab, two methods, the reference, 48x48.
printf '{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 5, "moving": true}, "radius": 0.025}' > seq.json
STUDY=(--methods spheres,aniso_ssf --reference reference -W 48 -H 48 --repeat 1 -q --no-cache)
"$BIN" compare seq.json "${STUDY[@]}" -o single 2> single.err
check '[ -s single/metrics.csv ]' "the single-process run"
body() { grep -v '^#' "$1" | cut -d, -f1-13,15-; }  # column 14 is frame_ms

# 1. four shards and the merge through submit.sh
bash "$SUBMIT" seq.json -o study "${STUDY[@]}" --shards 4 --bin "$BIN" > submit.out 2> submit.err; rc=$?
aid=$(awk '$1 == "array" {print $2}' submit.out) mid=$(awk '$1 == "merge" {print $2}' submit.out)
check '[ $rc -eq 0 ] && [ -n "$aid" ] && [ -n "$mid" ]' "submit.sh prints the array's and the merge's job ids ($aid, $mid)"
wait_jobs 120 "$aid" "$mid"; rc=$?
check '[ $rc -eq 0 ]' "the study ends within 120 s"
check '[ "$(job_state "$aid" | sort -u)" = COMPLETED ] && [ "$(job_state "$aid" | wc -l)" -eq 4 ] && [ "$(job_state "$mid")" = COMPLETED ]' "4 array tasks and the merge completed"
check 'scontrol -o show job "$mid" | grep -q "Dependency=(null)\|afterok:${aid}"' "the merge job depended on the array"
check 'for k in 1 2 3 4; do [ -f study/shards/$k/DONE ] || exit 1; done' "every shard wrote DONE"
check '[ -s study/metrics.csv ] && diff <(body single/metrics.csv) <(body study/metrics.csv) >/dev/null' "merged metrics.csv equals the single process's, timing columns aside"
check 'diff <(grep -v "^#" single/temporal.csv) <(grep -v "^#" study/temporal.csv) >/dev/null' "merged temporal.csv equals the single process's"
check 'grep -q "shards=4;" study/metrics.csv' "merged provenance says shards=4"

# 2. two broken array tasks, on a held array so the test decides before any runs:
# task 2 cancelled (it never starts), task 3 fails (its output folder is a file).
bash "$SUBMIT" seq.json -o broken "${STUDY[@]}" --shards 4 --bin "$BIN" -- --hold > b.out 2> b.err; rc=$?
aid=$(awk '$1 == "array" {print $2}' b.out) mid=$(awk '$1 == "merge" {print $2}' b.out)
check '[ $rc -eq 0 ] && [ -n "$aid" ] && [ -n "$mid" ]' "a second study submitted on hold ($aid, $mid)"
scancel "${aid}_2"
: > broken/shards/3
scontrol release "$aid" 2>/dev/null
wait_jobs 120 "$aid"
scontrol release "$mid" 2>/dev/null
wait_jobs 60 "$mid"
# a pending array task cancelled leaves no job record: the array shows the other three
check '[ "$(job_state "$aid" | sort | tr "\n" " ")" = "COMPLETED COMPLETED FAILED " ]' "tasks 1 and 4 completed, task 3 failed ($(job_state "$aid" | tr '\n' ' '))"
check '[ ! -e broken/shards/2/DONE ] && [ -f broken/shards/1/DONE ] && [ -f broken/shards/4/DONE ] && grep -q "shards/3: exists and is not a folder" broken/logs/shard-3-*.out' "the cancelled and the failed task leave no DONE, the failure is in its log"
check '[ "$(job_state "$mid")" = CANCELLED ] && [ ! -e broken/metrics.csv ]' "the merge job was cancelled (state $(job_state "$mid")), nothing merged"
rm broken/shards/3
bash "$SUBMIT" --resume broken -- --time=10 > r.out 2> r.err; rc=$?
raid=$(awk '$1 == "array" {print $2}' r.out) rmid=$(awk '$1 == "merge" {print $2}' r.out)
check '[ $rc -eq 0 ] && grep -q "shard(s) 2 3 of 4" r.err && [ -n "$raid" ] && [ -n "$rmid" ]' "--resume re-submits only shards 2 and 3 with a new merge ($(tr '\n' ' ' < r.err))"
wait_jobs 120 "$raid" "$rmid"
check '[ "$(job_state "$raid" | wc -l)" -eq 2 ] && scontrol -o show job "$raid" | grep -q "ArrayTaskId=3 "' "the re-submitted array ran tasks 2 and 3 alone"
check '[ "$(job_state "$rmid")" = COMPLETED ] && diff <(body single/metrics.csv) <(body broken/metrics.csv) >/dev/null' "the resumed study completes with the single process's metrics"
bash "$SUBMIT" --resume broken > r2.out 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "are done" r2.out' "--resume of a finished study submits nothing"

# 3. submit.sh's own refusals and --gpu, without a cluster round trip
bash "$SUBMIT" seq.json -o study "${STUDY[@]}" --shards 4 --bin "$BIN" > /dev/null 2> e1; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < e1)" -eq 1 ] && grep -q "already holds a study" e1' "a study folder in use is refused ($(cat e1))"
bash "$SUBMIT" seq.json -o x "${STUDY[@]}" --shards 0 --bin "$BIN" > /dev/null 2> e2; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < e2)" -eq 1 ] && grep -q "shards 0" e2 && [ ! -e x ]' "--shards 0 is refused, nothing made ($(cat e2))"
bash "$SUBMIT" --resume nostudy > /dev/null 2> e3; rc=$?
check '[ $rc -eq 2 ] && grep -q "not a study folder" e3' "--resume of a folder without a study is refused"
bash "$SUBMIT" seq.json -o gpu "${STUDY[@]}" --shards 2 --gpu --bin "$BIN" --dry-run > /dev/null 2> g.err; rc=$?
check '[ $rc -eq 0 ] && grep -q "^sbatch --array=1-2 --gres=gpu:1 " g.err && grep -q "afterok:.* --kill-on-invalid-dep=yes" g.err' "--gpu asks for --gres=gpu:1; the merge depends with afterok and --kill-on-invalid-dep=yes"
check 'grep -q -- "compare seq.json .*--gl egl --shard K/2" g.err && [ ! -e gpu ]' "--gpu renders through --gl egl; --dry-run makes nothing"

cluster_stop
alive=0; for p in $(cat "$T"/cluster/*.pid 2>/dev/null); do kill -0 "$p" 2>/dev/null && alive=1; done
check '[ $alive -eq 0 ]' "every daemon stopped"
echo "$((n - fails))/$n passed"
[ $fails -eq 0 ]
