#!/usr/bin/env bash
# Packs the lean build (scripts/build_lean.sh) into DIR for a bare machine: the
# fluidsurf binary, the lean experiment tools, and the shared libraries they link
# (resolved through ldd, copied as real files under their SONAME, C runtime
# excepted). The binaries' DT_RPATH $ORIGIN finds them there. --gl also copies
# this machine's GL loaders (glvnd: libEGL.so.1, libGLdispatch.so.0,
# libOpenGL.so.0), for a GPU node that has only the NVIDIA driver.
# usage: scripts/pack_lean.sh [--gl] [--build DIR] OUTDIR
set -euo pipefail
cd "$(dirname "$0")/.."
gl=0 build=build-lean out=
while [ $# -gt 0 ]; do
  case $1 in
    --gl) gl=1 ;;
    --build) build=$2; shift ;;
    -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "pack_lean: unknown option $1" >&2; exit 2 ;;
    *) [ -z "$out" ] || { echo "pack_lean: one output folder only" >&2; exit 2; }; out=$1 ;;
  esac
  shift
done
[ -n "$out" ] || { echo "usage: scripts/pack_lean.sh [--gl] [--build DIR] OUTDIR" >&2; exit 2; }
bins=("$build/fluidsurf")
for t in density_bench inacio_tables render_bench edge_bands; do
  [ -x "$build/experiments/$t" ] && bins+=("$build/experiments/$t")
done
[ -x "${bins[0]}" ] || { echo "pack_lean: ${bins[0]}: not built (run scripts/build_lean.sh)" >&2; exit 2; }
# shellcheck source=scripts/lean_libs.sh
source scripts/lean_libs.sh # lean_runtime
runtime=$lean_runtime
mkdir -p "$out"
copy_lib() { # SONAME PATH: the real file, under its SONAME
  cp -L "$2" "$out/$1.tmp.$$" && mv -f "$out/$1.tmp.$$" "$out/$1"
}
for b in "${bins[@]}"; do
  cp "$b" "$out/"
  ldd "$b" | while read -r name arrow path _; do
    [[ "$name" =~ $runtime || "$name" == /* || "$arrow" != "=>" ]] && continue
    [ -e "$path" ] || { echo "pack_lean: $b: $name not found" >&2; exit 1; }
    copy_lib "$name" "$path"
  done
done
if [ $gl = 1 ]; then
  for so in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0; do
    # read ldconfig's whole listing (over 64 kB): an awk that exits early would end it with
    # SIGPIPE, which pipefail turns into a silent failure of this script
    path=$(ldconfig -p | awk -v n="$so" '$1 == n && /x86-64/ && !found {print $NF; found = 1}')
    [ -n "$path" ] || { echo "pack_lean: $so not found on this machine (install libegl1 libopengl0)" >&2; exit 1; }
    copy_lib "$so" "$path"
  done
fi
# the commit the binaries were built from, for the CSVs of experiments/gpu/run.sh (the
# copy of the repository that travels with the pack has no .git)
source experiments/lib.sh # study_commit
study_commit > "$out/provenance"
echo "pack_lean: $out: $(ls "$out" | wc -l) files, $(du -sb "$out" | cut -f1) bytes"
ls -l "$out" | awk 'NR > 1 {printf "pack_lean:   %-28s %9d\n", $NF, $5}'
