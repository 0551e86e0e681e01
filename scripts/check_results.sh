#!/usr/bin/env bash
# Fails unless every committed CSV under results/ names, in its first '#' line, the commit
# its numbers were made at and a clean tree: "commit=<hash>" and "dirty=0" (fluidsurf's own
# provenance, or experiments/lib.sh: stamp_csv, csv_commit). A CSV assembled from other runs
# names theirs ("sources=NAME@HASH:dirty=0,..."), and each of those must be clean too.
# Lists every CSV that fails, with why.
# Each named commit must also be in this history or listed, with why, in
# experiments/tools/lost_commits.txt (commits of work whose landing was lost); a listed
# commit that no CSV names fails too, so that list only shrinks.
# experiments/tools/rerun_pending.txt lists CSVs known to predate this rule and not yet
# re-measured: each is reported as pending, not failed, and one that passes while still
# listed fails (take it off the list), so the list only shrinks.
#   check_results.sh [ROOT]   (default: this checkout; ROOT/results is checked)
set -u
cd "${1:-$(dirname "$0")/..}"
source experiments/lib.sh # PROV_RE
pending_list=experiments/tools/rerun_pending.txt
pending() { [ -f $pending_list ] && grep -qxF "$1" $pending_list; }
# Every commit a CSV names must be one a reader can check out: in this history, or listed
# with why in lost_commits.txt. Not checked outside git or in a shallow clone.
lost_list=experiments/tools/lost_commits.txt
check_commits=0
[ "$(git rev-parse --is-shallow-repository 2> /dev/null)" = false ] && check_commits=1
unknown_commit() {
  local h
  [ $check_commits = 1 ] || return 1
  for h in $(grep -oE '(commit=|@)[0-9a-f]{7,40}' <<< "$1" | grep -oE '[0-9a-f]{7,40}$'); do
    git cat-file -e "$h^{commit}" 2> /dev/null && continue
    grep -qE "^$h( |$)" $lost_list 2> /dev/null || { echo "$h"; return 0; }
  done
  return 1
}
bad=0 n=0 waiting=0 stale=0
while read -r f; do
  n=$((n + 1))
  first=$(grep -m1 '^#' "$f")
  why=""
  if [ -z "$first" ]; then why="no '#' provenance line"
  elif ! grep -qE -- "$PROV_RE" <<< "$first"; then why="its first '#' line names no commit=<hash> with dirty=0|1"
  elif grep -qE -- '-dirty|(^|[ ;])dirty=1' <<< "$first"; then why="made at a dirty tree"
  elif grep -qE 'sources=' <<< "$first" && grep -oE 'sources=[^ ;]*' <<< "$first" | tr ',' '\n' | grep -qv ':dirty=0$'; then
    why="assembled from a run at a dirty tree or without a commit"
  elif h=$(unknown_commit "$first"); then
    why="names commit $h, which this history does not hold (list it in $lost_list, with why, only if it is truly gone)"
  fi
  if [ -n "$why" ] && pending "$f"; then waiting=$((waiting + 1))
  elif [ -n "$why" ]; then echo "  $f: $why"; bad=$((bad + 1))
  elif pending "$f"; then echo "  $f: names a clean commit but is still in $pending_list: take it off"; bad=$((bad + 1)); fi
done < <(git ls-files 'results/*.csv' 'results/**/*.csv' | sort -u)
# A lost commit no committed CSV names any more was re-run away: take it off the list, so the
# list only shrinks (issue 56: its end state is no list at all).
if [ $check_commits = 1 ] && [ -f $lost_list ]; then
  for h in $(grep -oE '^[0-9a-f]{7,40}' $lost_list); do
    git grep -qF "$h" -- 'results/*.csv' 'results/**/*.csv' && continue
    echo "  $lost_list: $h is named by no committed CSV: take it off"; stale=$((stale + 1))
  done
fi
if [ $bad -gt 0 ]; then
  echo "check_results: $bad of $n committed CSVs do not name a clean commit in this history (re-run their study at a clean commit; never re-stamp)"
  exit 1
fi
[ $stale -gt 0 ] && { echo "check_results: $stale stale line(s) in $lost_list"; exit 1; }
if [ $waiting -gt 0 ]; then
  echo "check_results: $((n - waiting)) of $n committed CSVs name a clean commit; $waiting more predate the rule and await a re-run ($pending_list)"
else
  echo "check_results: $n committed CSVs, every one naming a clean commit (commit=, dirty=0)"
fi
