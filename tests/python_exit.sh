#!/usr/bin/env bash
# No crash at exit (issue 48): tests/python/exit_script.py (read, bad calls, mesh,
# compare, render, exit) RUNS times in a row with two busy loops keeping the CPU
# busy beside it; every run must exit 0. Before libfluidsurf was linked with
# -z nodelete, cffi's dlclose at interpreter exit unmapped the library and its
# libgomp while an OpenMP worker still spun there: SIGSEGV after all output.
# Runs alternate OpenMP's default wait policy (the user's case: the worker spins a
# while after each region; a few runs in a hundred crashed, more on a loaded
# machine) with OMP_WAIT_POLICY=active (it spins until the next region: every run
# crashed), so that the test fails on the old code whatever the machine's load.
# Usage: python_exit.sh PYTHON PARTICLES OUTDIR [RUNS]
set -u
PY=$1 DATA=$2 T=$3 RUNS=${4:-50}
rm -rf "$T"; mkdir -p "$T"
script=$(dirname "$0")/python/exit_script.py
busy_loop() { while :; do :; done; }
busy_loop & b1=$!
busy_loop & b2=$!
trap 'kill $b1 $b2 2> /dev/null' EXIT
fails=0 start=$SECONDS
for i in $(seq "$RUNS"); do
  policy=default
  [ $((i % 2)) -eq 0 ] && policy=active
  # ctest (and scripts/test.sh) may set a policy: each run gets its own
  if [ $policy = active ]; then env OMP_WAIT_POLICY=active "$PY" "$script" "$DATA" 24 > "$T/out" 2> "$T/err"
  else env -u OMP_WAIT_POLICY "$PY" "$script" "$DATA" 24 > "$T/out" 2> "$T/err"; fi
  rc=$?
  if [ $rc -ne 0 ] || ! grep -q '^True 1 (24, 24) True$' "$T/out"; then
    fails=$((fails + 1))
    echo "FAIL run $i (OMP_WAIT_POLICY $policy): exit $rc: $(tail -c 300 "$T/err")"
  fi
done
echo "$((RUNS - fails)) of $RUNS runs exited 0 ($((SECONDS - start)) s)"
[ $fails -eq 0 ]
