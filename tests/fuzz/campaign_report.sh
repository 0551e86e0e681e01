#!/usr/bin/env bash
# Writes the tables of README.md beside a campaign CSV (tests/fuzz/campaign.sh) from the
# CSV alone, between the "<!-- campaign table -->" and "<!-- end campaign table -->"
# lines, so that no number in the README is typed by hand; the text around them (what was
# found and fixed) is kept. A README that is not there yet is made from the template below.
#   tests/fuzz/campaign_report.sh [CSV]   (default results/fuzz/campaign.csv)
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # csv_awk
csv=${1:-results/fuzz/campaign.csv}
md=$(dirname "$csv")/README.md
[ -f "$csv" ] || { echo "campaign_report.sh: no $csv (tests/fuzz/campaign.sh writes it)" >&2; exit 2; }
if [ ! -f "$md" ]; then
  cat > "$md" << 'EOF'
# Fuzzing campaign

Made by `tests/fuzz/campaign.sh MINUTES` (tests/fuzz/README.md, "Campaigns"): every libFuzzer
target of `tests/fuzz/`, unseeded, from its committed seeds and what earlier campaigns kept,
under ASan and UBSan. The table below is generated from `campaign.csv` by
`tests/fuzz/campaign_report.sh`; do not edit it by hand. `runs` is libFuzzer's
`stat::number_of_executed_units`, `features` and `corpus_size` its last status line's `ft:` and
`corp:`; `open_findings` counts the inputs that still crash, leak, hang or run out of memory.
A row `NAME_mut` is the harness of `NAME` with its custom mutator, from the same corpus.

<!-- campaign table -->
<!-- end campaign table -->

## Found and fixed

(Each finding of a campaign, the reader's fix and its regression file under `tests/fuzz/regress_NAME/`.)
EOF
fi

table() {
  echo "Provenance: \`$(grep -m1 '^#' "$csv" | sed 's/^# *//')\`"
  echo
  echo "| target | minutes | runs | features | corpus size | open findings |"
  echo "|---|---:|---:|---:|---:|---:|"
  csv_awk 'printf "| %s | %s | %s | %s | %s | %s |\n", col("target"), col("minutes"), col("runs"), col("features"), col("corpus_size"), col("open_findings")' "$csv"
  echo
  # the custom mutators: the same harness and starting corpus, with and without
  csv_awk 'print col("target"), col("features"), col("minutes"), col("open_findings")' "$csv" | awk '
    { ft[$1] = $2; order[++n] = $1; open += $4; if (n == 1 || $3 + 0 < min) min = $3 + 0 }
    END {
      for (i = 1; i <= n; i++) {
        t = order[i]; b = t; if (!sub(/_mut$/, "", b) || !(b in ft)) continue
        printf "- Custom mutator of `%s`: %d features with it, %d without (%+.0f%%).\n", b, ft[t], ft[b], (ft[b] > 0 ? 100 * (ft[t] - ft[b]) / ft[b] : 0)
      }
      printf "- %d targets, each run for at least %s minutes; %d open findings.\n", n, min, open
    }'
}

tmp=$(mktemp)
table > "$tmp"
replace_block "$md" "campaign table" "$tmp"
rm -f "$tmp"
echo "updated $md"
