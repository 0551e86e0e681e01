#!/usr/bin/env python3
"""Writes a pivot of a study's long CSV as a new CSV, for a README's generated table:
one row per distinct value of the --rows columns, one column per value of --col,
cells from --val.

    pivot_csv.py IN OUT --rows A[,B...] --col C --val V [--cols v1,v2,...] [--where COL=V[|V...]]...

--cols picks and orders the --col values (default: all, in order of appearance);
--where keeps rows whose COL is one of the values. Empty cells where a combination is
missing. OUT's first line names IN and carries IN's first provenance line, so a table
made from OUT shows where its numbers were measured.
"""
import argparse
import csv
import os
import sys


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("src")
    p.add_argument("out")
    p.add_argument("--rows", required=True)
    p.add_argument("--col", required=True)
    p.add_argument("--val", required=True)
    p.add_argument("--cols", default="")
    p.add_argument("--where", action="append", default=[])
    a = p.parse_args()
    with open(a.src, newline="") as f:
        lines = f.read().splitlines()
    prov = next((l[1:].strip() for l in lines if l.startswith("#")), "")
    rows = list(csv.DictReader(l for l in lines if l and not l.startswith("#")))
    keys = a.rows.split(",")
    wheres = [w.split("=", 1) for w in a.where]
    if any(len(w) != 2 for w in wheres):
        sys.exit("pivot_csv.py: --where takes COL=VALUE[|VALUE...]")
    for c in keys + [a.col, a.val] + [w[0] for w in wheres]:
        if rows and c not in rows[0]:
            sys.exit("pivot_csv.py: %s has no column %s" % (a.src, c))
    cells, order, seen_cols = {}, [], []
    for r in rows:
        if any(r[c] not in v.split("|") for c, v in wheres):
            continue
        k = tuple(r[c] for c in keys)
        if k not in cells:
            cells[k] = {}
            order.append(k)
        cells[k][r[a.col]] = r[a.val]
        if r[a.col] not in seen_cols:
            seen_cols.append(r[a.col])
    cols = a.cols.split(",") if a.cols else seen_cols
    if not order:
        sys.exit("pivot_csv.py: %s: no rows left to pivot" % a.src)
    tmp = a.out + ".tmp"
    with open(tmp, "w", newline="") as f:
        f.write("# %s by %s, from %s: %s\n" % (a.val, a.col, os.path.basename(a.src), prov))
        w = csv.writer(f, lineterminator="\n")
        w.writerow(keys + cols)
        for k in order:
            w.writerow(list(k) + [cells[k].get(c, "") for c in cols])
    os.replace(tmp, a.out)


if __name__ == "__main__":
    main()
