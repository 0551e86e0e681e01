#!/usr/bin/env bash
# scripts/install.sh's plan (--dry-run: nothing is built) and its argument errors, its
# --install-only step on this build (BUILD), and cmake/openvdb.cmake's quiet: a project
# that finds OpenVDB through it prints no stray "COMPONENT = openvdb" line and still finds it.
set -u
SRC=$1 T=$2 BUILD=$3
rm -rf "$T"; mkdir -p "$T"
fails=0 n=0
check() { n=$((n + 1)); if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
inst=$SRC/scripts/install.sh

# 1. the default: build-install/ (configured without tests when new), only the installed targets
bash "$inst" --dry-run "$T/prefix" > "$T/plan" 2> "$T/plan.err"; rc=$?
check '[ $rc -eq 0 ] && grep -q "^cmake -S . -B build-install\( \|$\)" "$T/plan"' "the default build folder is build-install/: $(tr '\n' '|' < "$T/plan")"
check 'grep -qx "cmake --build build-install -j[0-9]* --target fluidsurf fluidsurf_lib" "$T/plan" && grep -qx "cmake --install build-install --prefix $T/prefix" "$T/plan"' \
  "builds only fluidsurf and fluidsurf_lib, installs into PREFIX"
check '! grep -q " build\( \|$\)" "$T/plan" && [ ! -e "$T/prefix" ]' "never the checkout's build/; --dry-run makes nothing"
bash "$inst" --dry-run --build "$T/fresh" "$T/prefix" > "$T/plan1" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -qx "cmake -S . -B $T/fresh -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFS_TESTS=OFF" "$T/plan1" && [ ! -e "$T/fresh" ]' \
  "a new build folder is configured with -DFS_TESTS=OFF"
# 2. --build DIR: an existing tree keeps its options (no -DFS_TESTS=OFF forced on it)
mkdir -p "$T/tree" && touch "$T/tree/CMakeCache.txt"
bash "$inst" --dry-run --build "$T/tree" "$T/prefix" > "$T/plan2" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -qx "cmake -S . -B $T/tree" "$T/plan2" && grep -q "^cmake --build $T/tree .*--target fluidsurf fluidsurf_lib$" "$T/plan2"' \
  "--build DIR: that tree, its own options, the same two targets"
# 3. bad arguments: exit 2, one line
for args in "--bogus" "--build" "--build --x" "a b"; do
  bash "$inst" --dry-run $args > /dev/null 2> "$T/bad.err"; rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/bad.err")" -eq 1 ] && grep -q "^install.sh: " "$T/bad.err"' "install.sh $args: exit 2, one line ($(cat "$T/bad.err"))"
done

# 4. --install-only: an existing build as it is (no apt, no configure, no build)
mkdir -p "$T/built" && touch "$T/built/CMakeCache.txt" "$T/built/fluidsurf" "$T/built/libfluidsurf.so.0"
bash "$inst" --dry-run --install-only --build "$T/built" "$T/prefix" > "$T/plan3" 2>&1; rc=$?
check '[ $rc -eq 0 ] && [ "$(cat "$T/plan3")" = "cmake --install $T/built --prefix $T/prefix" ]' \
  "--install-only: the install step alone ($(tr '\n' '|' < "$T/plan3"))"
rm "$T/built/libfluidsurf.so.0"
bash "$inst" --install-only --build "$T/built" "$T/prefix" > /dev/null 2> "$T/only.err"; rc=$?
check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/only.err")" -eq 1 ] && grep -q "has no libfluidsurf.so.0: build it first" "$T/only.err" && [ ! -e "$T/prefix" ]' \
  "--install-only of an unbuilt tree: exit 2, one line, nothing installed ($(cat "$T/only.err"))"
bash "$inst" --install-only --build "$T/none" "$T/prefix" > /dev/null 2> "$T/none.err"; rc=$?
check '[ $rc -eq 2 ] && grep -q "is not a build folder" "$T/none.err"' "--install-only of no build folder: exit 2 ($(cat "$T/none.err"))"
bash "$inst" --install-only --build "$BUILD" "$T/real" > "$T/real.out" 2>&1; rc=$?
check '[ $rc -eq 0 ] && "$T/real/bin/fluidsurf" --version > /dev/null && ls "$T"/real/lib*/libfluidsurf.so.0 > /dev/null && grep -q "^install: fluidsurf in $T/real" "$T/real.out"' \
  "--install-only of this build: the command and the library installed ($(tail -c 300 "$T/real.out"))"

# 5. OpenVDB found without the stray line
mkdir -p "$T/vdb"
cat > "$T/vdb/CMakeLists.txt" <<CM
cmake_minimum_required(VERSION 3.20)
project(quiet C CXX)
include($SRC/cmake/openvdb.cmake)
message(STATUS "found: \${OpenVDB_FOUND}")
CM
cmake -S "$T/vdb" -B "$T/vdb/b" > "$T/vdb.out" 2>&1; rc=$?
check '[ $rc -eq 0 ] && grep -q "found: TRUE" "$T/vdb.out" && ! grep -q "COMPONENT" "$T/vdb.out"' "cmake/openvdb.cmake finds OpenVDB and prints no COMPONENT line ($(grep -m1 COMPONENT "$T/vdb.out"))"

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
