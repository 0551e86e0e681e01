#!/usr/bin/env bash
# The installed library is usable from a program of one's own: examples/c builds
# against PREFIX with pkg-config and with CMake's find_package, runs, and gives
# the same metrics as fluidsurf's own compare of the same method.
set -u
SRC=$1 PREFIX=$2 T=$3 DATA=$4
rm -rf "$T"; mkdir -p "$T"
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }

export PKG_CONFIG_PATH="$PREFIX/lib/pkgconfig"
check 'pkg-config --exists fluidsurf && [ "$(pkg-config --modversion fluidsurf)" = 0.1.0 ]' "pkg-config finds fluidsurf 0.1.0"
check 'cc -Wall -Werror "$SRC/examples/c/render_compare.c" $(pkg-config --cflags --libs fluidsurf) -o "$T/by_pkgconfig" 2> "$T/cc.err"' \
  "the example compiles with pkg-config's flags: $(cat "$T/cc.err" 2>/dev/null)"
check 'cmake -S "$SRC/examples/c" -B "$T/cmake" -DCMAKE_PREFIX_PATH="$PREFIX" > "$T/cmake.log" 2>&1 && cmake --build "$T/cmake" > "$T/build.log" 2>&1' \
  "the example builds with find_package(fluidsurf)"
# the program needs the library from PREFIX: found through its run path or LD_LIBRARY_PATH
for exe in "$T/by_pkgconfig" "$T/cmake/render_compare"; do
  LD_LIBRARY_PATH="$PREFIX/lib" "$exe" "$DATA" raycast_pca 0.025 96 > "$exe.out" 2> "$exe.err"; rc=$?
  check '[ $rc -eq 0 ] && grep -q "^24389 particles, r = 0.025, 96x96" "$exe.out"' "$(basename "$exe") runs: $(head -c 300 "$exe.err")"
  check 'grep -Eq "^raycast_pca against reference: IoU 0\.9[0-9]+, depth RMSE [0-9.]+ r, normal error [0-9.]+ deg" "$exe.out"' \
    "$(basename "$exe") prints plausible metrics: $(sed -n 3p "$exe.out")"
  check 'grep -Eq "^  (march|splat).* ms  llvmpipe" "$exe.out"' "$(basename "$exe") names the renderer of its GL stages"
  iou=$(sed -n 's/^raycast_pca against reference: IoU \([0-9.]*\),.*/\1/p' "$exe.out")
  check 'grep -q "^method,variant,reference,frame,mask_iou," "$exe.out" && awk -F, -v want="$iou" '"'"'$1 == "raycast_pca" && $3 == "reference" {found = 1; if (sprintf("%.4f", $5) != want) exit 1} END {exit !found}'"'"' "$exe.out"' \
    "$(basename "$exe") runs the study (fluidsurf_compare): metrics.csv's columns, the same IoU as its render ($iou)"
done
check 'cmp -s <(sed -n 3p "$T/by_pkgconfig.out") <(sed -n 3p "$T/cmake/render_compare.out")' "both builds give the same metrics"
# a bad file: the library's one-line message, no crash
LD_LIBRARY_PATH="$PREFIX/lib" "$T/by_pkgconfig" "$T/missing.ply" raycast_pca > /dev/null 2> "$T/bad.err"; rc=$?
check '[ $rc -eq 1 ] && [ "$(wc -l < "$T/bad.err")" -eq 1 ] && grep -q "missing.ply" "$T/bad.err"' "a missing file: one line naming it ($(cat "$T/bad.err"))"
[ $fails -eq 0 ] && echo "all passed" || { echo "$fails failed"; exit 1; }
