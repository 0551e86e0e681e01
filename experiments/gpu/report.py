#!/usr/bin/env python3
"""Tables of one experiments/gpu/run.sh folder beside the papers' numbers.

    python3 experiments/gpu/report.py DIR > DIR/tables.md

Every number comes from DIR's CSVs (medians over the timed runs); the papers'
numbers are the ones their tables print. Frame times are the sums of a method's
own stages (no load, grid build, upload or shading), as in experiments/xiao2017/
table1.sh and experiments/xu2022/fig9.sh."""
import csv
import os
import statistics
import sys
from collections import defaultdict

T1_STAGES = ("splat", "march", "normals", "filter", "thickness", "readback")
F9_STAGES = ("anisotropy", "splat", "filter", "normals", "thickness", "readback")
# xiao2017 Table 1 (seconds, GTX 970): particle count -> {size: s}
XIAO_N = (779752, 2027776, 12394215, 37975520, 142612764)
XIAO_T = {512: (0.00936, 0.0274, 0.0891, 0.1565, 0.5926), 768: (0.0127, 0.0362, 0.1128, 0.2119, 0.6600),
          1024: (0.0178, 0.05138, 0.1568, 0.2966, 0.7840), 1440: (0.0270, 0.0779, 0.2474, 0.4494, 1.3879),
          1920: (0.0424, 0.1226, 0.3733, 0.7062, 2.3663)}


def rows(d, name):
    path = os.path.join(d, name)
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:  # the provenance line starts with '#'
        return [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]


def num(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return None


def frames(rs, stages, key):
    """Per cell (key(row)) the median over runs of the sum of the stages on the wall clock, and
    of the stages that have one (all but the read back) on the GL clock."""
    wall, gpu = defaultdict(lambda: defaultdict(float)), defaultdict(lambda: defaultdict(float))
    for r in rs:
        if r["stage"] in stages and r["run"] != "0":
            k = key(r)
            wall[k][r["run"]] += float(r["ms"])
            g = num(r["gpu_ms"])
            if g is not None:
                gpu[k][r["run"]] += g
    med = lambda runs: statistics.median(runs.values()) if runs else None
    return {k: (med(wall[k]), med(gpu[k])) for k in wall}


def fmt(x, p="%.1f"):
    return "" if x is None or x != x else p % x


def table(head, body):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    return "\n".join(out) + "\n"


def xiao(d):
    rs = rows(d, "xiao2017_table1.csv")
    if not rs:
        return "No xiao2017 rows.\n"
    fr = frames(rs, T1_STAGES, lambda r: (int(r["particles"]), int(r["size"])))
    body = []
    for (n, size), (w, g) in sorted(fr.items()):
        i = min(range(len(XIAO_N)), key=lambda j: abs(XIAO_N[j] - n) / XIAO_N[j])
        paper = XIAO_T.get(size, (None,) * 5)[i] if abs(XIAO_N[i] - n) / XIAO_N[i] < 0.05 else None
        body.append((n, size, fmt(w), fmt(g), fmt(paper * 1e3 if paper else None),
                     fmt(paper * 1e3 / w if paper else None, "%.2f")))
    return table(("particles", "size", "frame ms (wall)", "GL stages ms (GL clock)", "paper ms (GTX 970)",
                  "paper / ours"), body)


def xu(d):
    rs = rows(d, "xu2022_fig9.csv")
    if not rs:
        return "No xu2022 rows.\n"
    fr = frames(rs, F9_STAGES, lambda r: (int(r["particles"]), r["variant"]))
    body = [(n, v.replace("aniso_ssf.", "").replace(";", ", "), fmt(w), fmt(g)) for (n, v), (w, g) in sorted(fr.items())]
    return table(("particles", "variant", "frame ms (wall)", "GL stages ms (GL clock)"), body)


def inacio(d):
    rs = rows(d, "inacio2010_tables.csv")
    if not rs:
        return "No inacio2010 rows.\n"
    per = defaultdict(lambda: defaultdict(list))  # (n, path) -> stage -> [ms per frame]
    for r in rs:
        per[(int(r["particles"]), r["path"])][(r["table"], r["stage"])].append(float(r["ms"]))
    med = lambda v: statistics.median(v) if v else None
    body = []
    for (n, path), st in sorted(per.items()):
        sim = med(st[("sim", "simulation")])
        vol = med(st[("I", "volume")])
        ray = med([a + b for a, b in zip(st[("I", "faces")], st[("I", "march")])])
        sph = med(st[("II", "splat")])
        body.append((n, path, fmt(sim), fmt(vol), fmt(ray), fmt(sph)))
    ratios = []
    for (n, path), st in sorted(per.items()):
        if path == "cpu" and (n, "gpu") in per:
            c, g = med(st[("sim", "simulation")]), med(per[(n, "gpu")][("sim", "simulation")])
            ratios.append((n, fmt(c / g if c and g else None, "%.2f")))
    return (table(("fluid particles", "path", "simulation ms", "volume ms", "ray casting ms", "spheres splat ms"), body)
            + "\nSimulation, CPU path / GPU path. The paper (Core 2 Duo against GeForce 9800M GS): the CPU path "
              "was faster at 1024 and 2048 particles, the GPU path took under a third of its time at 8192.\n\n"
            + table(("fluid particles", "cpu / gpu"), ratios))


def iwasaki(d):
    rs = rows(d, "iwasaki2006_density_grid.csv")
    if not rs:
        return "No iwasaki2006 rows.\n"
    cell = defaultdict(list)
    for r in rs:
        cell[(int(r["particles"]), int(r["res"]), r["method"])].append(r)
    body = []
    for (n, res, m) in sorted(k for k in cell if k[2] == "exact_cpu"):
        ex = statistics.median(float(r["ms"]) for r in cell[(n, res, m)])
        sp = cell.get((n, res, "slice_splat"), [])
        w = statistics.median(float(r["ms"]) for r in sp) if sp else None
        gs = [num(r["gpu_ms"]) for r in sp if num(r["gpu_ms"]) is not None]
        g = statistics.median(gs) if gs else None
        l2 = max(float(r["rel_l2_vs_exact"]) for r in sp) if sp else None
        body.append((n, res, fmt(ex), fmt(w), fmt(g), fmt(ex / w if w else None, "%.1f"), fmt(l2, "%.3g")))
    return (table(("particles", "res", "exact CPU ms", "slice splat ms (wall)", "slice splat ms (GL clock)",
                   "CPU / GL", "rel. L2"), body)
            + "\nThe paper (GeForce 6800 GT): about 210,000 particles into 256^3, 0.91 s on the GPU against "
              "about 80 s in software, 88x; relative difference 1.9%.\n")


def demo(d):
    rs = rows(d, "demo_timings.csv")
    body = [(r["method"], r["variant"], r["ms_median"], r["renderer"]) for r in rs if r["stage"] == "total"]
    return table(("method", "variant", "total ms (wall)", "renderer"), body) if body else "No demo rows.\n"


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "results/gpu"
    env = {r["key"]: r["value"] for r in rows(d, "env.csv")}
    print("Run: %s, %s mode; GL_RENDERER %s, GL_VERSION %s; %s.\n" % (
        env.get("date", "?"), env.get("mode", "?"), env.get("gl_renderer", "?"), env.get("gl_version", "?"),
        env.get("gpu", "no nvidia-smi")))
    for title, f in (("xiao2017 Table 1 (raycast_pca)", xiao), ("xu2022 Fig. 9 (aniso_ssf)", xu),
                     ("inacio2010 Tables I and II", inacio), ("iwasaki2006 density grid", iwasaki),
                     ("Demo comparison", demo)):
        print("### %s\n\n%s" % (title, f(d)))
    skipped = [r for r in rows(d, "status.csv") if r["exit"] != "0"]
    if skipped:
        print("### Cells that did not finish\n\n" + table(("step", "cell", "exit", "note"),
              [(r["step"], r["cell"], r["exit"], r["note"]) for r in skipped]))


if __name__ == "__main__":
    main()
