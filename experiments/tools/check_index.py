#!/usr/bin/env python3
"""Checks the commit column of results/README.md's index against the CSVs: each row's
commit must be the one in the provenance line of its main CSV (the first CSV its analogue
column links), or "none recorded" when that CSV names none. Lists each row that differs.

    python3 experiments/tools/check_index.py [results/README.md]
"""
import os
import re
import sys

COMMIT = re.compile(r"commit[=: ]+([0-9a-f]{7,40})(-dirty)?")


def csv_commit(path):
    """(commit, dirty) of a CSV's first line, or None when it names no commit."""
    with open(path) as f:
        line = f.readline()
    m = COMMIT.search(line)
    # a dirty tree is written "-dirty" after the commit, or "dirty=1" (experiments/lib.sh)
    return (m.group(1), bool(m.group(2)) or "dirty=1" in line) if m else None


def check_row(cells, folder):
    """An error message for one index row, or None."""
    links = re.findall(r"\]\(([^)]+\.csv)\)", cells[2])
    if not links:
        return "links no CSV"
    path = os.path.join(folder, links[0])
    if not os.path.exists(path):
        return "%s does not exist" % links[0]
    got, col = csv_commit(path), cells[4]
    if got is None:
        return None if col.startswith("none recorded") else "%s names no commit, the row says %s" % (links[0], col)
    m = COMMIT.match("commit=" + col)
    if not m:
        return "%s names commit %s, the row says %s" % (links[0], got[0], col)
    short = min(len(m.group(1)), len(got[0]))
    if m.group(1)[:short] != got[0][:short] or bool(m.group(2)) != got[1]:
        return "%s names commit %s%s, the row says %s" % (links[0], got[0], "-dirty" if got[1] else "", col)
    return None


def main():
    readme = sys.argv[1] if len(sys.argv) > 1 else "results/README.md"
    if not os.path.isfile(readme):
        sys.stderr.write("check_index: %s: no such file\n" % readme)
        sys.exit(2)
    folder = os.path.dirname(os.path.abspath(readme))
    bad, n = [], 0
    for line in open(readme):
        if not line.startswith("| ") or line.startswith("| item |"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if len(cells) != 5:
            bad.append("%s: %d columns, not 5" % (cells[0], len(cells)))
            continue
        n += 1
        err = check_row(cells, folder)
        if err:
            bad.append("%s: %s" % (cells[0], err))
    for b in bad:
        print("check_index: %s: %s" % (readme, b))
    if bad or not n:
        sys.exit("check_index: %d of %d rows differ from their CSVs" % (len(bad), n))
    print("check_index: %s: %d rows, each commit equal to its main CSV's" % (readme, n))


if __name__ == "__main__":
    main()
