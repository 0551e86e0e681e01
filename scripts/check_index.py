#!/usr/bin/env python3
"""Checks the commit column of results/README.md's index against the CSVs: each row's
commit must be the one in the provenance line of its main CSV (the first CSV its analogue
column links), or "none recorded" when that CSV names none. Lists each row that differs.

    python3 scripts/check_index.py [--fix] [results/README.md]

--fix writes each row's commit column from its main CSV (after a study is re-run).
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


def fix_rows(readme, folder):
    """Rewrites each row's commit column from its main CSV; prints each change."""
    out = []
    for line in open(readme):
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if line.startswith("| ") and not line.startswith("| item |") and len(cells) == 5 and check_row(cells, folder):
            links = re.findall(r"\]\(([^)]+\.csv)\)", cells[2])
            got = csv_commit(os.path.join(folder, links[0])) if links and os.path.exists(os.path.join(folder, links[0])) else None
            if got and not got[1]:
                print("check_index: %s: %s -> %s" % (cells[0], cells[4], got[0]))
                cells[4] = got[0]
                line = "| " + " | ".join(cells) + " |\n"
        out.append(line)
    with open(readme + ".tmp", "w") as f:
        f.write("".join(out))
    os.replace(readme + ".tmp", readme)


def main():
    args = [a for a in sys.argv[1:] if a != "--fix"]
    readme = args[0] if args else "results/README.md"
    if not os.path.isfile(readme):
        sys.stderr.write("check_index: %s: no such file\n" % readme)
        sys.exit(2)
    folder = os.path.dirname(os.path.abspath(readme))
    if "--fix" in sys.argv[1:]:
        fix_rows(readme, folder)
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
