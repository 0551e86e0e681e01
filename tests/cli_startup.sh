#!/usr/bin/env bash
# What a command loads before it does its work (docs/DESIGN.md, "Start-up"): commands
# that make no GL context and draw no text (--version, info, a reference render to
# PNG or EXR) load neither the OpenImageIO module nor OpenImageIO, nor OSMesa and the
# LLVM it brings (opened at the first OSMesa context); a render through a GL context
# does open its GL library. Read from the loader's own record (LD_DEBUG=files).
#   cli_startup.sh BIN SRC T WITH_OSMESA
set -u
BIN=$1 SRC=$2 T=$3 OSMESA=$4
rm -rf "$T"; mkdir -p "$T"
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
bgeo=$SRC/experiments/data/splashsurf/dam_break_frame_9_6859_particles.bgeo # every build reads BGEO
heavy='fluidsurf-oiio|libOpenImageIO|libOSMesa|libLLVM|libEGL|libGL'
# loads NAME CMD...: the libraries CMD opened, one a line, in $T/NAME.libs
loads() {
  local name=$1; shift
  LD_DEBUG=files "$@" > /dev/null 2> "$T/$name.ld" || fail "$name: $(grep -v '^ *[0-9]*:' "$T/$name.ld" | head -3)"
  grep -o 'file=[^ ]*' "$T/$name.ld" | sed 's/^file=//' | sort -u > "$T/$name.libs"
}
loads version "$BIN" --version
loads info "$BIN" info "$bgeo"
loads png "$BIN" render "$bgeo" --method reference -W 8 -H 8 -q -o "$T/r.png"
loads exr "$BIN" render "$bgeo" --method reference -W 8 -H 8 -q -o "$T/r.exr"
for name in version info png exr; do
  if grep -Eq "$heavy" "$T/$name.libs"; then
    fail "$name loaded $(grep -E "$heavy" "$T/$name.libs" | tr '\n' ' ')"
  else
    echo "ok   $name: $(wc -l < "$T/$name.libs") libraries, none of $heavy"
  fi
done
# a GL method opens its context's library when it needs it
gl=libEGL; [ "$OSMESA" = 1 ] && gl=libOSMesa
loads gl "$BIN" render "$bgeo" --method spheres -W 8 -H 8 -q -o "$T/s.png"
grep -q "$gl" "$T/gl.libs" && echo "ok   a GL render opened $gl" || fail "a GL render did not open $gl"

[ $fails -eq 0 ] && echo "cli_startup: all passed" || { echo "cli_startup: $fails failed"; exit 1; }
