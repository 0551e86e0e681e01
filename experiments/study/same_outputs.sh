#!/usr/bin/env bash
# same_outputs.sh OLD NEW [DIR]: the outputs of two fluidsurf builds, file for file, byte for
# byte but for times and the commit and command line they record (issue 50: the study's
# folder moved out of cli/ into common/study_dir and was to change no byte). OLD and NEW are
# fluidsurf binaries or commits; a commit's fluidsurf is built (that target alone, through
# ccache) in a detached worktree under DIR, removed afterwards. Each build runs, in the same
# folder (DIR/work) with the same arguments, at small sizes:
#   demo      scripts/demo.sh's compare at the quick size (128x128, --repeat 1)
#   sweep     spheres swept over two parameters beside raycast_pca, with counters; then
#             sweep_resumed: a copy without raycast_pca.exr, finished by --resume
#   seq_*     a ten-frame slab sequence (experiments/scenes/slab_sequence.json) storing its
#             references into an empty cache (seq_store), then the same hitting it (seq_hit)
#   shards/K  a five-frame moving slab, two methods, two references, in three shards;
#             merged: the three merged
# then tests/same_study.py --any-commit compares each folder of OLD with NEW's (panel.png
# aside: its captions hold frame times). Prints each difference, one line; exit 1 when any.
# DIR (default out/same_outputs) is emptied first.
set -Eeuo pipefail
cd "$(dirname "$0")/../.."
src=$PWD
[ $# -ge 2 ] || { echo "usage: $0 OLD NEW [DIR] (a fluidsurf binary or a commit each)" >&2; exit 2; }
dir=$(realpath -m "${3:-out/same_outputs}")
rm -rf "$dir"
mkdir -p "$dir"
trees=()
cleanup() { for t in "${trees[@]}"; do git worktree remove --force "$t" 2> /dev/null || true; done; }
trap cleanup EXIT

# binary_of BIN|COMMIT: sets $binary, the fluidsurf to run (a commit is built into DIR/src-COMMIT)
binary_of() {
  if [ -f "$1" ] && [ -x "$1" ]; then binary=$(realpath "$1"); return; fi
  local c t
  c=$(git rev-parse --short=10 "$1^{commit}")
  t=$dir/src-$c
  git worktree add --detach "$t" "$c" > /dev/null 2>&1
  trees+=("$t")
  export CCACHE_BASEDIR=$t # the cache's entries shared with other checkouts of the commit
  source scripts/compiler_cache.sh # FS_LAUNCHER
  cmake -S "$t" -B "$t/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${FS_LAUNCHER[@]}" > /dev/null
  cmake --build "$t/build" -j"$(nproc)" --target fluidsurf > /dev/null
  binary=$t/build/fluidsurf
}

# studies BIN: every run above into DIR/work (the same paths for both builds)
studies() {
  local bin=$1 scenes=$src/experiments/scenes zb=""
  # not grep -q: under pipefail its early exit can fail the pipe (SIGPIPE to methods)
  if "$bin" methods 2> /dev/null | grep '^mesh ' > /dev/null; then zb="--set mesh.field=isotropic,zhu_bridson"; fi
  mkdir -p "$dir/work" && cd "$dir/work"
  # shellcheck disable=SC2086 # $zb is a list of arguments or none
  "$bin" compare --force --no-cache "$scenes/dam_break.json" -o demo -W 128 -H 128 --repeat 1 $zb -q
  local sweep=("$scenes/box.json" --methods spheres,raycast_pca --set spheres.radius_scale=0.8,1.2
    --set spheres.thickness=on,off -W 48 -H 48 --repeat 1 --counters --no-cache -q)
  "$bin" compare "${sweep[@]}" -o sweep
  cp -r sweep sweep_resumed && rm sweep_resumed/raycast_pca.exr
  "$bin" compare "${sweep[@]}" --resume -o sweep_resumed
  local seq=("$scenes/slab_sequence.json" --methods spheres,aniso_ssf -W 48 -H 48 --repeat 1 --cache cache -q)
  "$bin" compare "${seq[@]}" -o seq_store
  "$bin" compare "${seq[@]}" -o seq_hit
  printf '{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 4, "moving": true}, "radius": 0.025}' > moving.json
  local sh=(moving.json --methods spheres,aniso_ssf --reference reference --reference analytic -W 48 -H 48 --repeat 1
    -q --no-cache --counters)
  mkdir -p shards
  for k in 1 2 3; do "$bin" compare "${sh[@]}" --shard $k/3 -o shards/$k; done
  "$bin" merge shards/1 shards/2 shards/3 -o merged -q
  cd "$src"
}

binary_of "$1" && old=$binary
binary_of "$2" && new=$binary
for b in old new; do
  trap 'echo "$0: the $b build'"'"'s studies failed: $(tail -1 "$dir/$b.err")" >&2' ERR
  studies "${!b}" 2> "$dir/$b.err" # set -e: a failing run ends the script here
  mv "$dir/work" "$dir/$b"
done
trap - ERR
bad=0
for s in demo sweep sweep_resumed seq_store seq_hit shards/1 shards/2 shards/3 merged; do
  echo "== $s"
  python3 tests/same_study.py --any-commit --skip panel.png "$dir/old/$s" "$dir/new/$s" || bad=1
done
exit $bad
