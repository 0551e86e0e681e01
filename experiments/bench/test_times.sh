#!/usr/bin/env bash
# The test command's time (issue 51): every stage of scripts/test.sh, every ctest of each
# build and every quick study, wall and CPU seconds, as results/bench/test_times.csv (one
# row each) and results/bench/test_stages.csv (one row a stage), with the tables in
# results/bench/README-tests.md.
#
#   experiments/bench/test_times.sh --run STAGE,...   runs those stages of scripts/test.sh
#                                                     (--only), every ctest timed per test
#   experiments/bench/test_times.sh                   writes the CSVs from what the runs left
#                                                     in out/test_times/ and out/run_all/
#
# Run each stage at one clean commit, the timed ones on a quiet machine and in pieces short
# enough for it (e.g. `quiet experiments/bench/test_times.sh --run ctest`); a build stage
# may run first under `busy`, its time then taken from a quiet re-run or left as measured.
# Wall times are as ctest and the shell saw them (ctest -j2: two tests share the 2 cores);
# CPU times are user + system of the test and every child it waited for (/usr/bin/time,
# experiments/tools/ctest_cpu.py), which other work on the machine barely moves.
set -euo pipefail
cd "$(dirname "$0")/../.."
T=out/test_times
if [ "${1:-}" = --run ]; then
  stages=${2:?usage: experiments/bench/test_times.sh [--run STAGE,...]}
  builds=()
  [[ ,$stages, == *,ctest,* ]] && builds+=(build)
  [[ ,$stages, == *,lean_ctest,* ]] && builds+=(build-lean)
  [[ ,$stages, == *,asan_ctest,* ]] && builds+=(build-asan)
  for b in "${builds[@]}"; do
    rm -rf "$T/cpu/$b"
    python3 experiments/tools/ctest_cpu.py wrap "$b" "$PWD/$T/cpu/$b"
  done
  unwrap() { for b in "${builds[@]}"; do python3 experiments/tools/ctest_cpu.py unwrap "$b"; done; }
  trap unwrap EXIT
  bash scripts/test.sh --only "$stages"
  exit 0
fi
python3 experiments/tools/test_times.py "$T" out/run_all/times.csv results/bench
python3 experiments/tools/csv_table.py --all results/bench/README-tests.md
echo "test_times: results/bench/test_times.csv, test_stages.csv, README-tests.md"
