#!/usr/bin/env python3
"""Writes a CSV as a Markdown table into a README, between the markers
    <!-- table: PATH -->  and  <!-- /table -->
where PATH is the CSV's path relative to the README's folder, optionally
followed by cols=a,b,c (those columns only, in that order). The CSV's leading
'# ...' provenance line is shown under the table. So a README's numbers are the
CSV's, regenerated, never typed.

    csv_table.py CSV README      replace the CSV's blocks (one must exist in README)
    csv_table.py --all README    regenerate every block of README
    csv_table.py --check README  exit 1 when a block differs from its CSV
"""
import csv
import os
import sys


def table(path, cols=None):
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    prov = [l[1:].strip() for l in lines if l.startswith("#")]
    rows = list(csv.reader(l for l in lines if l and not l.startswith("#")))
    if cols:
        missing = [c for c in cols if c not in rows[0]]
        if missing:
            raise SystemExit("csv_table.py: %s has no column %s" % (path, ", ".join(missing)))
        idx = [rows[0].index(c) for c in cols]
        rows = [[r[i] if i < len(r) else "" for i in idx] for r in rows]
    out = ["| " + " | ".join(rows[0]) + " |", "|" + "---|" * len(rows[0])]
    out += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    if prov:
        out += ["", "<sub>%s: %s</sub>" % (os.path.basename(path), prov[0])]
    return "\n".join(out)


def blocks(text):
    """(start, end, csv path) of each generated block, end past its closing marker."""
    at = 0
    while True:
        a = text.find("<!-- table: ", at)
        if a < 0:
            return
        e = text.index("-->", a)
        b = text.index("<!-- /table -->", e) + len("<!-- /table -->")
        yield a, b, text[a + len("<!-- table: "):e].strip()
        at = b


def block(spec, readme):
    """The block of marker text spec ("PATH" or "PATH cols=a,b")."""
    rel, *opts = spec.split()
    cols = None
    for o in opts:
        if not o.startswith("cols="):
            raise SystemExit("%s: unknown table option '%s' (only cols=a,b,...)" % (readme, o))
        cols = o[len("cols="):].split(",")
    path = os.path.join(os.path.dirname(os.path.abspath(readme)), rel)
    return "<!-- table: %s -->\n%s\n<!-- /table -->" % (spec, table(path, cols))


def main(argv):
    if len(argv) == 3 and argv[1] == "--check":
        text = open(argv[2]).read()
        stale = [rel for a, b, rel in blocks(text) if text[a:b] != block(rel, argv[2])]
        for rel in stale:
            print("%s: the table of %s is not the CSV's (run its experiment or csv_table.py)" % (argv[2], rel), file=sys.stderr)
        return 1 if stale else 0
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    readme = argv[2]
    text = open(readme).read()
    if argv[1] == "--all":
        found = [(a, b, spec) for a, b, spec in blocks(text)]
    else:
        rel = os.path.relpath(os.path.abspath(argv[1]), os.path.dirname(os.path.abspath(readme)))
        found = [(a, b, spec) for a, b, spec in blocks(text) if spec.split()[0] == rel]
        if not found:
            print("%s: no '<!-- table: %s -->' block to fill" % (readme, rel), file=sys.stderr)
            return 2
    for a, b, spec in reversed(found):
        text = text[:a] + block(spec, readme) + text[b:]
    with open(readme + ".tmp", "w") as f:
        f.write(text)
    os.replace(readme + ".tmp", readme)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
