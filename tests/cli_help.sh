#!/usr/bin/env bash
# Every command's --help (generated from its option table, cli/options.c) exits 0
# and lists exactly the options below, each with a help text; the parser takes
# each shared one; an unknown option fails with exit 2 and one line. A new
# option goes into its command's table and into the list here.
set -u
BIN=$1 T=$2
rm -rf "$T"; mkdir -p "$T"
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }

declare -A want=(
  [render]="--method -o --set -W --width -H --height --radius --up --volume-scale --iso --support --kernel --camera --camera-from --save-scene --format --frame --frames --gl --require-gpu --timings --counters --export --appearance --cache -q"
  [compare]="-o --methods --set --reference --import --repeat --normal-scale --depth-scale --cache --no-cache --resume --force --shard --counters -W --width -H --height --radius --up --volume-scale --iso --support --kernel --camera --camera-from --frames --gl --require-gpu -q"
  [merge]="-o --force -q"
  [report]=""
  [diff]="--fail-iou --fail-normal-deg --fail-depth-r --fail-depth-p95-r --fail-interior-normal-deg --fail-ssim --fail-psnr --radius --strict --json -o --normal-scale --depth-scale"
  [info]="--radius --volume-scale --format"
  [convert]="-o --from --to"
  [methods]=""
  [simulate]="--frames -o --particles --cpu --gpu --gl --require-gpu --eos --fps --dt --substeps --radius --nu --sound-speed --k --cfl --shake --shake-period --stats -q"
  [view]="--simulate --particles --gpu --dt --method --set -W --width -H --height --scale --radius --up --volume-scale --iso --support --kernel --require-gpu --paused --frames -v --script --events"
)

shared="-o -W --width -H --height --gl --set -q --radius"

# one_line_exit2 ARGS...: exit 2 and exactly one stderr line "fluidsurf: ..."
one_line_exit2() {
  "$BIN" "$@" > /dev/null 2> "$T/err"
  local rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q '^fluidsurf: ' "$T/err"
}

# FS_NO_VIEW=1: a build without GLFW, whose view only refuses (tests/cli_lean.sh checks that).
cmds="render compare merge report diff info convert methods simulate"
[ "${FS_NO_VIEW:-0}" = 1 ] || cmds="$cmds view"
for cmd in $cmds; do
  bad=$fails
  "$BIN" $cmd --help > "$T/help_$cmd" 2> "$T/err"; rc=$?
  [ $rc -eq 0 ] && [ ! -s "$T/err" ] || fail "$cmd --help: exit $rc, stderr: $(cat "$T/err")"
  head -1 "$T/help_$cmd" | grep -q "^usage: fluidsurf $cmd " || fail "$cmd --help: no usage line: $(head -1 "$T/help_$cmd")"
  # option lines: two spaces, the names ("-W, --width"), a metavar, two spaces, the help
  nohelp=$(grep '^  -' "$T/help_$cmd" | grep -Ev '^  -[^ ]+( [^ ]+)*  +[^ ]')
  [ -z "$nohelp" ] || fail "$cmd: options without a help text: $nohelp"
  listed=$(grep '^  -' "$T/help_$cmd" | awk '{ print $1; if ($1 ~ /,$/) print $2 }' | tr -d , | sort | tr '\n' ' ')
  expected=$(printf '%s\n' ${want[$cmd]} -h --help | sort | tr '\n' ' ')
  [ "$listed" = "$expected" ] || fail "$cmd --help lists: $listed; expected: $expected"
  for opt in ${want[$cmd]}; do
    # the parser takes opt (and a value), then stops at the unknown option, in one
    # line; only the shared options, as each run costs a start-up (~0.3 s)
    case " $shared " in *" $opt "*) ;; *) continue ;; esac
    one_line_exit2 $cmd "$opt" 1 --zz-unknown && ! grep -qF -- "option '$opt'" "$T/err" ||
      fail "$cmd does not take $opt: $(cat "$T/err")"
  done
  one_line_exit2 $cmd --zz-unknown && grep -qxF "fluidsurf: unknown or incomplete option '--zz-unknown' (try 'fluidsurf $cmd --help')" "$T/err" ||
    fail "$cmd --zz-unknown: $(cat "$T/err")"
  [ $fails -eq $bad ] && echo "ok   $cmd"
done

# the shared options read the same everywhere: one definition
bad=$fails
for opt in "--set M.P=V" "--gl osmesa|egl" "--require-gpu " "-q "; do
  texts=$(cat "$T"/help_* | grep -F -- "  $opt" | sed 's/  */ /g' | sort -u)
  [ "$(printf '%s\n' "$texts" | grep -c .)" -le 1 ] || fail "'$opt' has different help texts: $texts"
done
[ $fails -eq $bad ] && echo "ok   shared options"

echo "$fails failed"
[ $fails -eq 0 ]
