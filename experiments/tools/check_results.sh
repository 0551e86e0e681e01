#!/usr/bin/env bash
# Fails when a committed CSV under results/ was generated at a dirty tree: its provenance
# names a commit ending in -dirty, or dirty=1 (experiments/lib.sh, study_commit). Lists each.
set -u
cd "$(dirname "$0")/../.."
bad=$(git ls-files 'results/*.csv' | while read -r f; do
  grep -m1 -qE -- '-dirty|dirty=1' "$f" && echo "$f"
done)
if [ -n "$bad" ]; then
  echo "check_results: CSVs generated at a dirty tree (rerun their study at a clean commit):"
  echo "$bad" | sed 's/^/  /'
  exit 1
fi
echo "check_results: $(git ls-files 'results/*.csv' | wc -l) committed CSVs, every one from a clean commit"
