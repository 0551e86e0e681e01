#!/usr/bin/env bash
# Checks what a lean binary ($1, default build-lean/fluidsurf) links, through ldd:
# at most 10 libraries beyond the C runtime (libc, libm, libdl, libpthread, librt,
# ld-linux, linux-vdso), at most 8 MB together (the real files' sizes), and none
# of the heavy ones the lean build leaves out. Prints the list; exit 1 on a breach.
set -euo pipefail
bin=${1:-build-lean/fluidsurf}
[ -x "$bin" ] || { echo "check_lean: $bin: no such executable" >&2; exit 2; }
out=$(ldd "$bin") || { echo "check_lean: ldd $bin failed" >&2; exit 1; }
# shellcheck source=scripts/lean_libs.sh
source "$(dirname "$0")/lean_libs.sh" # lean_runtime
runtime=$lean_runtime
heavy='vtk|openvdb|OpenImageIO|tbb|boost|LLVM|OSMesa|libGL\.|libGLX|glapi|glfw'
n=0 total=0 fail=0
while read -r name arrow path _; do
  [ -n "$name" ] || continue
  if [[ "$name" =~ $runtime ]] || [[ "$name" == /* && "$name" =~ ld-linux ]]; then continue; fi
  if [ "$arrow" != "=>" ] || [ ! -e "$path" ]; then
    echo "check_lean: $name: not found" >&2; fail=1; continue
  fi
  size=$(stat -L -c %s "$path")
  n=$((n + 1)) total=$((total + size))
  printf 'check_lean: %-28s %8d bytes  %s\n' "$name" "$size" "$(readlink -f "$path")"
  if echo "$name" | grep -Eqi "$heavy"; then echo "check_lean: $name must not be linked" >&2; fail=1; fi
done <<< "$out"
printf 'check_lean: %d libraries beyond the C runtime, %d bytes together\n' "$n" "$total"
[ "$n" -le 10 ] || { echo "check_lean: more than 10 libraries" >&2; fail=1; }
[ "$total" -le $((8 * 1024 * 1024)) ] || { echo "check_lean: more than 8 MB of libraries" >&2; fail=1; }
exit $fail
