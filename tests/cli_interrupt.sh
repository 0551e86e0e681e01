#!/usr/bin/env bash
# Long work cut short or starved (issue 16): SIGINT and SIGTERM leave only finished
# outputs and say what was finished (exit 130, 143); compare --resume completes an
# interrupted study with the same metrics; progress is a bar on a terminal (run under
# script), a line per item otherwise, nothing with -q; a full disk (a tmpfs this test
# mounts, when it may) exits 1 and keeps the earlier file; a device node is never
# replaced by an output.
#   cli_interrupt.sh BIN SRC T
set -u
BIN=$1 SRC=$2 T=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
seq_scene=$SRC/experiments/scenes/slab_sequence.json
ply=$SRC/experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply
study=(compare "$seq_scene" --methods spheres,raycast_pca -W 96 -H 96 --repeat 1 --no-cache)
# metrics.csv without its provenance line and its timing column (frame_ms, column 14)
metrics() { grep -v '^#' "$1/metrics.csv" | cut -d, -f1-13,15-; }

# Starts "$@" in the background (stderr to $T/$name.err), waits until its stderr has
# a line matching pattern (at most 120 s), sends the signal, and leaves its exit code in rc.
interrupt_after() {
  local name=$1 signal=$2 pattern=$3; shift 3
  "$BIN" "$@" 2> "$T/$name.err" & local pid=$!
  for _ in $(seq 1200); do grep -q "$pattern" "$T/$name.err" 2> /dev/null && break; sleep 0.1; done
  kill -s "$signal" $pid; wait $pid; rc=$?
}
no_temporaries() { [ -z "$(find "$1" -name '.*.tmp*' 2> /dev/null)" ]; }

# 1. the study as one uninterrupted run
"$BIN" "${study[@]}" -q -o "$T/whole" 2> "$T/whole.err"
check '[ $? -eq 0 ] && [ -s "$T/whole/metrics.csv" ]' "the uninterrupted study runs"

# 2. SIGINT after the first method items (the 10 references come first): exit 130,
# one last line, only finished outputs
interrupt_after int INT '13/30 work items' "${study[@]}" -o "$T/cut"
check '[ $rc -eq 130 ]' "SIGINT exits 130 (got $rc)"
last=$(tail -1 "$T/int.err")
check '[[ $last =~ ^fluidsurf:\ interrupted\ \(SIGINT\)\ after\ [0-9]+\ of\ 30\ work\ items\ finished ]]' "one line says what was finished: $last"
check 'no_temporaries "$T/cut"' "no temporary file is left"
check '[ ! -e "$T/cut/metrics.csv" ]' "no table of an unfinished study"
bad=0
for f in "$T"/cut/*.exr; do "$BIN" diff "$f" "$f" > /dev/null 2>&1 || bad=$((bad + 1)); done
check '[ $bad -eq 0 ] && ls "$T"/cut/*.exr > /dev/null 2>&1' "every EXR left is complete ($(ls "$T"/cut/*.exr 2> /dev/null | wc -l) of them)"

# 3. --resume finishes it: some items loaded, the metrics those of the whole run
"$BIN" "${study[@]}" --resume -o "$T/cut" 2> "$T/resume.err"
check '[ $? -eq 0 ]' "compare --resume completes the study"
loaded=$(sed -n 's/.*--resume: \([0-9]*\) work item.*/\1/p' "$T/resume.err")
check '[ "${loaded:-0}" -ge 3 ] && [ "$loaded" -lt 30 ]' "it loads the finished items and renders the rest (loaded ${loaded:-none})"
check 'diff <(metrics "$T/whole") <(metrics "$T/cut") > /dev/null' "resumed metrics equal the uninterrupted run's"
check 'diff <(grep -v "^#" "$T/whole/temporal.csv" | cut -d, -f1-2) <(grep -v "^#" "$T/cut/temporal.csv" | cut -d, -f1-2) > /dev/null' "so do the temporal rows"
# an item of another run (other parameters) is not taken
"$BIN" "${study[@]}" --set spheres.radius_scale=0.8 --resume -q -o "$T/cut" 2> "$T/other.err"
check '[ $? -eq 0 ] && ! diff <(metrics "$T/whole") <(metrics "$T/cut") > /dev/null' "items rendered with other parameters are rendered again"

# 4. SIGTERM during simulate: exit 143, the frames written stay readable
mkdir -p "$T/sim"
interrupt_after term TERM '3/' simulate dam_break --particles 4000 --frames 400 -o "$T/sim/f_%04d.ply"
check '[ $rc -eq 143 ]' "SIGTERM exits 143 (got $rc)"
check 'tail -1 "$T/term.err" | grep -q "^fluidsurf: terminated (SIGTERM) after [0-9]* of 401 frames finished"' "and says how many frames: $(tail -1 "$T/term.err")"
check 'no_temporaries "$T/sim"' "no temporary frame is left"
bad=0
for f in "$T"/sim/f_*.ply; do "$BIN" info "$f" > /dev/null 2>&1 || bad=$((bad + 1)); done
check '[ $bad -eq 0 ]' "every frame written is readable ($(ls "$T"/sim/f_*.ply | wc -l))"

# 5. progress: a bar with an ETA on a terminal, a line per item otherwise, nothing with -q
script -qec "$BIN mesh '$seq_scene' --set mesh.cube=1 -o '$T/m_{}.ply'" "$T/tty.txt" > /dev/null 2>&1
check 'grep -q "mesh \[#*\.*\] .*ETA" "$T/tty.txt"' "a bar with an ETA on a terminal"
"$BIN" mesh "$seq_scene" --set mesh.cube=1 -o "$T/m_{}.ply" 2> "$T/lines.err"
check '[ "$(grep -c "^fluidsurf: mesh: [0-9]*/10 frames: frame" "$T/lines.err")" -eq 10 ]' "one line per frame off a terminal"
script -qec "$BIN mesh '$seq_scene' --set mesh.cube=1 -q -o '$T/m_{}.ply'" "$T/quiet.txt" > /dev/null 2>&1
check '! grep -q "mesh \[" "$T/quiet.txt"' "-q: no bar"

# 6. a device node as the output: refused, untouched
if mknod "$T/node.png" c 1 3 2> /dev/null; then
  "$BIN" render "$ply" --method spheres -W 32 -H 32 -o "$T/node.png" 2> "$T/node.err"; rc=$?
  check '[ $rc -eq 2 ] && [ -c "$T/node.png" ] && [ "$(wc -l < "$T/node.err")" -eq 1 ]' "a device node is not replaced (exit $rc: $(cat "$T/node.err"))"
else
  echo "note: mknod not permitted here; the device node case needs root"
fi
mkfifo "$T/fifo.exr"
"$BIN" render "$ply" --method spheres -W 32 -H 32 -o "$T/fifo.exr" 2> "$T/fifo.err"; rc=$?
check '[ $rc -eq 2 ] && [ -p "$T/fifo.exr" ]' "nor a FIFO (exit $rc)"

# 7. a full disk: exit 1, one line, the earlier file intact, nothing left behind
mkdir -p "$T/full"
if mount -t tmpfs -o size=256k tmpfs "$T/full" 2> /dev/null; then
  trap 'umount "$T/full" 2> /dev/null' EXIT
  for out in a.png a.exr a.ply; do
    printf 'earlier file\n' > "$T/full/$out"
    cp "$T/full/$out" "$T/earlier"
    dd if=/dev/zero of="$T/full/fill" bs=1k count=1024 2> /dev/null # fills it
    case $out in
      *.ply) "$BIN" convert "$ply" -o "$T/full/$out" 2> "$T/full.err" ;;
      *) "$BIN" render "$ply" --method spheres -W 128 -H 128 -o "$T/full/$out" 2> "$T/full.err" ;;
    esac
    rc=$?
    check '[ $rc -eq 1 ] && [ "$(wc -l < "$T/full.err")" -eq 1 ] && cmp -s "$T/full/$out" "$T/earlier" && no_temporaries "$T/full"' \
      "full disk, $out: exit $rc, $(cat "$T/full.err"), the earlier file kept"
    rm -f "$T/full/fill"
  done
  umount "$T/full"; trap - EXIT
else
  echo "note: cannot mount a tmpfs here (not root); the full-disk cases need it"
fi

echo "cli_interrupt: $((n - fails))/$n passed"
[ $fails -eq 0 ]
