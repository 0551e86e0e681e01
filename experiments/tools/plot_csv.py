#!/usr/bin/env python3
"""Plots a study's CSV as lines with gnuplot: y against x, one line per series.

    plot_csv.py CSV PNG --x COL --y COL [--series COL[,COL...]] [--where COL=V[|V...]]...
                [--logx] [--logy] [--title T] [--xlabel T] [--ylabel T]

--where keeps rows whose COL is one of the values (repeatable: all must hold).
Rows whose x or y is not a number are left out. The CSV's '# ...' provenance line
(its first 100 characters) is printed under the title, so a plot names its source.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile


def number(v):
    try:
        f = float(v)
    except ValueError:
        return None
    return f if f == f and abs(f) != float("inf") else None


def read(path):
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    prov = next((l[1:].strip() for l in lines if l.startswith("#")), "")
    rows = list(csv.DictReader(l for l in lines if l and not l.startswith("#")))
    return prov, rows


def series_of(rows, a):
    """{series name: [(x, y)]} in the CSV's order of first appearance."""
    cols = [c for c in (a.series.split(",") if a.series else []) if c]
    wheres = [w.split("=", 1) for w in a.where]
    for c in [a.x, a.y] + cols + [w[0] for w in wheres]:
        if rows and c not in rows[0]:
            sys.exit("plot_csv.py: %s has no column %s" % (a.csv, c))
    out = {}
    for r in rows:
        if any(r[c] not in v.split("|") for c, v in wheres):
            continue
        x, y = number(r[a.x]), number(r[a.y])
        if x is None or y is None or (a.logx and x <= 0) or (a.logy and y <= 0):
            continue
        name = ", ".join("%s %s" % (c, r[c]) for c in cols) or a.y
        out.setdefault(name, []).append((x, y))
    return out


def gnuplot_script(a, prov, data_files):
    q = lambda s: "'" + s.replace("'", "''") + "'"
    dq = lambda s: '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    lines = ["set terminal pngcairo size 900,560 font ',10' noenhanced", "set output %s" % q(a.png),
             "set title %s" % dq((a.title or "%s against %s" % (a.y, a.x)) + "\n" + prov[:100]),
             "set xlabel %s" % q(a.xlabel or a.x), "set ylabel %s" % q(a.ylabel or a.y),
             "set grid", "set key outside right top"]
    if a.logx:
        lines.append("set logscale x")
    if a.logy:
        lines.append("set logscale y")
    plots = ["%s using 1:2 with linespoints lw 2 title %s" % (q(f), q(name)) for name, f in data_files]
    lines.append("plot " + ", ".join(plots))
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("--x", required=True)
    p.add_argument("--y", required=True)
    p.add_argument("--series", default="")
    p.add_argument("--where", action="append", default=[])
    p.add_argument("--logx", action="store_true")
    p.add_argument("--logy", action="store_true")
    p.add_argument("--title", default="")
    p.add_argument("--xlabel", default="")
    p.add_argument("--ylabel", default="")
    a = p.parse_args()
    if any("=" not in w for w in a.where):
        sys.exit("plot_csv.py: --where takes COL=VALUE[|VALUE...]")
    prov, rows = read(a.csv)
    series = series_of(rows, a)
    if not series:
        sys.exit("plot_csv.py: %s: no rows to plot" % a.csv)
    with tempfile.TemporaryDirectory() as d:
        files = []
        for i, (name, pts) in enumerate(series.items()):
            f = os.path.join(d, "s%d.dat" % i)
            with open(f, "w") as out:
                out.writelines("%r %r\n" % xy for xy in sorted(pts))
            files.append((name, f))
        script = os.path.join(d, "plot.gp")
        tmp_png = a.png + ".tmp.png"
        final, a.png = a.png, tmp_png
        with open(script, "w") as out:
            out.write(gnuplot_script(a, prov, files))
        r = subprocess.run(["gnuplot", script])
        if r.returncode:
            if os.path.exists(tmp_png):
                os.remove(tmp_png)
            sys.exit("plot_csv.py: gnuplot failed on %s" % final)
        os.replace(tmp_png, final)
    print("wrote", final)


if __name__ == "__main__":
    main()
