#!/usr/bin/env bash
# Runs a command under xvfb-run with the command's own output and exit status.
# xvfb-run's messages show only when the command did not run: after the command it can
# fail to remove its temporary folder ("problem while cleaning up temporary directory",
# exit 5, seen once in the sanitizer ctest), which is no failure of the command.
# usage: tests/xvfb.sh WxHxDEPTH COMMAND...
set -u
screen=$1
shift
d=$(mktemp -d) || exit 1
exec 3>&2
xvfb-run -a -s "-screen 0 $screen" bash -c '"$@" 2>&3 3>&-; echo $? > "$0"' "$d/rc" "$@" 2> "$d/xvfb.err"
x=$?
if [ -s "$d/rc" ]; then
  rc=$(cat "$d/rc")
else
  cat "$d/xvfb.err" >&2
  rc=$((x == 0 ? 1 : x))
fi
rm -rf "$d"
exit "$rc"
