#!/usr/bin/env bash
# Regenerates the tables of results/bench/README-memory.md from
# results/bench/memory.csv (experiments/bench/memory.sh), between the
# "<!-- memory table -->" and "<!-- end memory table -->" lines, so that no
# measured number in the README is typed by hand.
# Bytes per particle = growth of the median peak RSS / growth of n, between
# consecutive particle counts of the same state, input and method.
# FS_QUICK=1 (memory.sh's quick mode): reads out/quick/results/bench/memory.csv and writes the
# tables into out/quick/results/bench/README-memory.md (a copy of the committed one the first
# time); results/ is never touched.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # RESULTS
csv=$RESULTS/bench/memory.csv
md=$RESULTS/bench/README-memory.md
if [ "$FS_QUICK" = 1 ] && [ ! -f "$md" ] && [ -f results/bench/README-memory.md ]; then
  mkdir -p "$(dirname "$md")"; cp results/bench/README-memory.md "$md"
fi
[ -f "$csv" ] && [ -f "$md" ] || { echo "memory_table.sh: needs $csv and $md" >&2; exit 2; }

# summary: bytes per particle per (input, method, n range), one column per state.
summary() {
  grep -v '^#' "$csv" | grep -v '^state,' | sort -t, -k1,1 -k2,2r -k3,3 -k4,4n |
  awk -F, '{
      key = $1 "," $2 "," $3
      if (key == last) {
        row = $2 "," $3 "," prev_n "," $4
        if (!(row in seen)) { seen[row] = 1; rows[++nr] = row }
        bpp[$1 "," row] = sprintf("%.0f", ($7 - prev_kib) * 1024 / ($4 - prev_n))
      }
      if (!($1 in st)) { st[$1] = 1; states[++ns] = $1 }
      last = key; prev_n = $4; prev_kib = $7
    }
    END {
      # "before" first, then the other states in name order
      for (i = 1; i <= ns; i++) for (j = i + 1; j <= ns; j++)
        if (states[j] == "before" || (states[i] != "before" && states[j] < states[i])) { t = states[i]; states[i] = states[j]; states[j] = t }
      head = "| input | method | n from | n to |"; sep = "|---|---|---:|---:|"
      for (i = 1; i <= ns; i++) { head = head " " states[i] " |"; sep = sep "---:|" }
      print head; print sep
      for (r = 1; r <= nr; r++) {
        split(rows[r], f, ","); line = "| " f[1] " | " f[2] " | " f[3] " | " f[4] " |"
        for (i = 1; i <= ns; i++) { k = states[i] "," rows[r]; line = line " " ((k in bpp) ? bpp[k] : "—") " |" }
        print line
      }
    }'
}

table() {
  echo "Bytes per particle (growth of the median peak RSS over growth of n):"
  echo
  summary
  echo
  echo "All cells:"
  echo
  echo "| state | input | method | n | peak RSS (MiB, median) | runs | bytes per particle from the previous n |"
  echo "|---|---|---|---:|---:|---:|---:|"
  grep -v '^#' "$csv" | grep -v '^state,' | sort -t, -k1,1r -k2,2r -k3,3 -k4,4n |
  awk -F, '{
      key = $1 "," $2 "," $3
      bpp = (key == last) ? sprintf("%.0f", ($7 - prev_kib) * 1024 / ($4 - prev_n)) : "—"
      printf "| %s | %s | %s | %d | %.0f | %d | %s |\n", $1, $2, $3, $4, $7 / 1024, $6, bpp
      last = key; prev_n = $4; prev_kib = $7
    }'
  echo
  echo "Provenance (from the CSV header):"
  echo
  grep '^# state ' "$csv" | sed 's/^# /- /'
}

tmp=$(mktemp)
table > "$tmp"
replace_block "$md" "memory table" "$tmp"
rm -f "$tmp"
echo "updated $md"
