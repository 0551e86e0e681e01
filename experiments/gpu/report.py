#!/usr/bin/env python3
"""The README of one experiments/gpu/run.sh folder: each paper's speed table beside ours,
as ratios and trends. Every number of ours comes from the folder's CSVs (medians over the
timed runs); the papers' numbers are the ones their tables and text print.

    python3 experiments/gpu/report.py DIR > DIR/README.md
    python3 experiments/gpu/report.py --tables DIR > DIR/tables.csv
    python3 experiments/gpu/report.py --check DIR      exit 1 when DIR/README.md or DIR/tables.csv is stale
    python3 experiments/gpu/report.py --bounds DIR     exit 1 when the run breaks a bound the next GPU run
                                                       must meet (the two marches of inacio2010's Table I)

tables.csv holds every number of the README's tables, unrounded, one a row (table, the row's
first one or two cells as key and sub, column, value), so that prose elsewhere can cite them
(scripts/check_numbers.py).

Frame times are the sums of a method's own stages (no load, grid build or upload), as in
experiments/xiao2017/table1.sh and experiments/xu2022/fig9.sh; fluidsurf shades on the CPU
after the read back of the G-buffer, and each table says which of its columns include the
read back, the shading and, for the simulator, how many steps a frame takes. The papers draw
and shade on their GPUs and read nothing back."""
import csv
import io
import os
import statistics
import sys
from collections import defaultdict

RASTER = ("splat", "thickness")  # raycast_pca's sprite stages: vertex + fragment work
SPLAT_COMPUTE = ("splat_compute", "splat_compute64", "thickness_compute")  # the same on the compute splatter
COMPUTE = ("march", "normals", "filter")  # its compute-shader stages
T1_STAGES = RASTER + SPLAT_COMPUTE + COMPUTE + ("readback",)
F9_STAGES = ("anisotropy", "splat", "filter", "normals", "thickness", "readback") + SPLAT_COMPUTE
FILTERS = ("none", "gaussian", "bilateral", "curvature", "narrow")
# xiao2017 Table 1 (seconds, GTX 970): particle count -> {size: s}
XIAO_N = (779752, 2027776, 12394215, 37975520, 142612764)
XIAO_T = {512: (0.00936, 0.0274, 0.0891, 0.1565, 0.5926), 768: (0.0127, 0.0362, 0.1128, 0.2119, 0.6600),
          1024: (0.0178, 0.05138, 0.1568, 0.2966, 0.7840), 1440: (0.0270, 0.0779, 0.2474, 0.4494, 1.3879),
          1920: (0.0424, 0.1226, 0.3733, 0.7062, 2.3663)}
# inacio2010 Tables I and II (seconds; Core 2 Duo P8400, GeForce 9800M GS): (particles, path) ->
# (simulation, volume generation, ray casting, rendering) and (simulation, sphere rendering).
# Table I's GPU row at 8192 is missing from our copy of the paper's text.
INACIO_I = {(1024, "cpu"): (0.022, 0.0075, 0.0076, 0.00051), (1024, "gpu"): (0.0029, 0.020, 0.034, 0.0013),
            (2048, "cpu"): (0.042, 0.0098, 0.0078, 0.00097), (2048, "gpu"): (0.0025, 0.021, 0.034, 0.0053),
            (4096, "cpu"): (0.078, 0.013, 0.0078, 0.00062), (4096, "gpu"): (0.0034, 0.024, 0.034, 0.0056),
            (8192, "cpu"): (0.19, 0.037, 0.010, 0.00087)}
INACIO_II = {(1024, "cpu"): (0.021, 0.013), (1024, "gpu"): (0.0015, 0.0077), (2048, "cpu"): (0.083, 0.046),
             (2048, "gpu"): (0.0024, 0.017), (4096, "cpu"): (0.080, 0.044), (4096, "gpu"): (0.0033, 0.033),
             (8192, "cpu"): (0.199, 0.091), (8192, "gpu"): (0.0058, 0.060)}


def rows(d, name):
    path = os.path.join(d, name)
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:  # the provenance line starts with '#'
        rs = list(csv.DictReader(line for line in f if not line.startswith("#")))
    # a row cut short (a tool killed at its time limit mid-line) is left out
    return [r for r in rs if None not in r.values() and None not in r and num(r.get("ms", "0")) is not None]


def provenance(d, name):
    path = os.path.join(d, name)
    if not os.path.exists(path):
        return "%s missing" % name
    with open(path) as f:
        first = f.readline()
    return first[1:].strip() if first.startswith("#") else "no provenance line"


def machine(d):
    """env.csv of a run folder as a dict (date, mode, gl_renderer, gpu, clocks, ...)."""
    return {r["key"]: r["value"] for r in rows(d, "env.csv")}


def num(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return None


def med(v):
    v = [x for x in v if x is not None]
    return statistics.median(v) if v else None


class Num(str):
    """A number as a table prints it that keeps its value, for tables.csv."""

    def __new__(cls, text, value):
        s = super().__new__(cls, text)
        s.value = value
        return s


def fmt(x, p="%.1f"):
    return "" if x is None or x != x else Num(p % x, x)


def ratio(a, b, p="%.2f"):
    return fmt(a / b if a is not None and b else None, p)


CELLS = []  # (table, key, sub, column, value) of every number the README's tables print


def table(head, body, name=None, keys=2):
    """A Markdown table; with a name, its numbers go to CELLS, each under its row's first
    `keys` cells (key and sub) and its column's head."""
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    for row in body if name else ():
        sub = str(row[1]) if keys > 1 else ""
        for col, c in zip(head[keys:], row[keys:]):
            v = c.value if isinstance(c, Num) else c if isinstance(c, (int, float)) else None
            if v is not None:
                CELLS.append((name, str(row[0]), sub, col, v))
    return "\n".join(out) + "\n"


def stage_medians(rs, key):
    """key(row) -> stage -> (median wall ms, median GL-clock ms) over the timed runs (run > 0)."""
    wall, gl = defaultdict(lambda: defaultdict(list)), defaultdict(lambda: defaultdict(list))
    for r in rs:
        if r["run"] != "0":
            wall[key(r)][r["stage"]].append(float(r["ms"]))
            gl[key(r)][r["stage"]].append(num(r["gpu_ms"]))
    return {k: {s: (med(wall[k][s]), med(gl[k][s])) for s in wall[k]} for k in wall}


def frames(rs, stages, key):
    """Per cell (key(row)) the median over runs of the sum of the stages on the wall clock, and
    of the GL stages (those with a GL-clock time: all but the read back) on the GL clock."""
    wall, gpu = defaultdict(lambda: defaultdict(float)), defaultdict(lambda: defaultdict(float))
    for r in rs:
        if r["stage"] in stages and r["run"] != "0":
            k = key(r)
            wall[k][r["run"]] += float(r["ms"])
            g = num(r["gpu_ms"])
            if g is not None:
                gpu[k][r["run"]] += g
    return {k: (med(wall[k].values()), med(gpu[k].values())) for k in wall}


def splat_path(v):
    """The sprite passes' path of a variant string: compute (splat=compute or compute32) or raster."""
    return "compute" if "splat=compute" in v else "raster"


def raster_rows(rs):
    """The rows of the raster path (every row of a run made before the compute splatter)."""
    return [r for r in rs if splat_path(r["variant"]) == "raster"]


def paper_xiao(n, size):
    """The paper's seconds for the set nearest n (within 5%) at size, else None."""
    i = min(range(len(XIAO_N)), key=lambda j: abs(XIAO_N[j] - n) / XIAO_N[j])
    return XIAO_T.get(size, (None,) * 5)[i] if abs(XIAO_N[i] - n) / XIAO_N[i] < 0.05 else None


def pick(values, want):
    """want if it is among values, else the middle value."""
    values = sorted(values)
    return want if want in values else values[len(values) // 2]


def xiao(d):
    everything = rows(d, "xiao2017_table1.csv")
    rs = raster_rows(everything)
    if not rs:
        return "No xiao2017 rows.\n"
    fr = frames(rs, T1_STAGES, lambda r: (int(r["particles"]), int(r["size"])))
    body = []
    for (n, size), (w, g) in sorted(fr.items()):
        p = paper_xiao(n, size)
        body.append((n, size, fmt(g), fmt(w), fmt(p * 1e3 if p else None), ratio(p * 1e3 if p else None, g)))
    out = XIAO_COLUMNS + table(("particles", "size", "ours ms (GL clock)", "ours ms (wall, + read back)",
                                "paper ms (GTX 970)", "paper / ours (GL clock)"), body, "xiao2017_table1")
    return (out + "\n" + EXCLUDED % "xiao2017 builds a GPU hash grid for its neighbour searches (its implementation "
            "notes) and does not say whether Table 1 includes it" + "\n" + setup_table(rs, "xiao2017_setup") + "\n"
            + xiao_trends(fr) + "\n" + xiao_stages(rs) + xiao_splat(everything))


XIAO_COLUMNS = ("Columns: *ours (GL clock)* is the sum of raycast_pca's GL stages (splat, march, normals, filter, "
                "thickness) on the GL clock, without the read back of the G-buffer, the shading (on the CPU, not "
                "timed here) and the once-per-set work below; *ours (wall)* adds the read back, on the wall clock. "
                "*paper* is Table 1's rendering time of xiao2017's method, which ends in its shading on the GPU "
                "(section 3.4). So *paper / ours* sets our frame without shading against the paper's with it: "
                "below 1, ours is slower while doing less.\n\n")


def xiao_trends(fr):
    ns, sizes = sorted({n for n, _ in fr}), sorted({s for _, s in fr})
    g = {k: v[1] for k, v in fr.items()}
    p = {k: paper_xiao(*k) for k in fr}
    s = pick(sizes, 1024)
    lines = ["Trends (GL clock; the paper's numbers from its Table 1):", ""]
    lo, hi = (ns[0], s), (ns[-1], s)
    lines.append("- **Particle count** at %d^2: %.0fx the particles cost %s the time here; the paper: %s." % (
        s, ns[-1] / ns[0], times(g.get(hi), g.get(lo), "(a cell missing)"), times(p.get(hi), p.get(lo), "no cell")))
    for n in (ns[0], ns[-1]):
        a, b = (n, sizes[0]), (n, sizes[-1])
        lines.append("- **Image size** at %d particles: %.1fx the pixels (%d^2 to %d^2) cost %s the time here; the "
                     "paper: %s." % (n, (sizes[-1] / sizes[0]) ** 2, sizes[0], sizes[-1],
                                     times(g.get(b), g.get(a), "(a cell missing)"), times(p.get(b), p.get(a), "no cell")))
    slower = [k for k in fr if g[k] and p[k] and p[k] * 1e3 < g[k]]
    if slower:
        worst = max(slower, key=lambda k: g[k] / (p[k] * 1e3))
        lines.append("- **Against the paper's times**: ours is slower in %d of the %d cells the paper has, by up to "
                     "%.1fx (%d particles at %d^2), without the shading the paper's frame includes." % (
                         len(slower), sum(1 for k in fr if p[k] is not None), g[worst] / (p[worst] * 1e3), *worst))
    rt = [k for k in fr if g[k] is not None and g[k] <= 1000 / 30]
    prt = [k for k in fr if p[k] is not None and p[k] <= 1 / 30]
    lines.append("- **Real time** (at most 33.3 ms, 30 fps): %d of %d cells here, %d of the %d the paper has." % (
        len(rt), len(fr), len(prt), sum(1 for k in fr if p[k] is not None)))
    big = [n for n in ns if n >= 30e6]
    if big:
        n = big[0]
        lines.append("- **Over 30M particles** (%d): %s fps at %d^2 here (the paper: %s fps), %s fps at %d^2 (the paper: "
                     "%s fps)." % (n, fps(g.get((n, sizes[0]))), sizes[0], fps(p.get((n, sizes[0])), 1),
                                   fps(g.get((n, sizes[-1]))), sizes[-1], fps(p.get((n, sizes[-1])), 1)))
    return "\n".join(lines) + "\n"


def times(a, b, missing):
    """'Nx' of a over b, or missing when a cell is not there."""
    r = ratio(a, b, "%.1f")
    return r + "x" if r else missing


EXCLUDED = ("What the frame leaves out: the neighbour grid, built on the CPU once per particle set, and the upload "
            "of the particles (both below, run 0), as fluidsurf renders many frames of one set; %s. A paper "
            "whose frame includes that work would be compared with more than our frame.\n")


def setup_table(rs, name):
    """The once-per-set stages (run 0) of a render_bench CSV, per particle count: median over variants."""
    per = defaultdict(lambda: defaultdict(list))
    for r in rs:
        if r["run"] == "0":
            per[int(r["particles"])][r["stage"]].append(num(r["ms"]))
    body = [(n, fmt(med(per[n]["load"])), fmt(med(per[n]["grid"])), fmt(med(per[n]["upload"]))) for n in sorted(per)]
    return table(("particles", "load or generate ms", "neighbour grid ms (CPU)", "upload ms"), body, name, keys=1)


def fps(t, unit_ms=1000):
    return fmt(unit_ms / t if t else None)


def xiao_stages(rs):
    """Where the time goes: the sprite (raster) stages against the compute stages."""
    st = stage_medians(rs, lambda r: (int(r["particles"]), int(r["size"])))
    sizes = sorted({s for _, s in st})
    body = []
    for (n, size) in sorted(st):
        if size not in (sizes[0], sizes[-1]):
            continue
        ras = sum(st[(n, size)].get(x, (0, 0))[1] or 0 for x in RASTER)
        com = sum(st[(n, size)].get(x, (0, 0))[1] or 0 for x in COMPUTE)
        rb = st[(n, size)].get("readback", (None, None))[0]
        body.append((n, size, fmt(ras), fmt(com), fmt(100 * ras / (ras + com) if ras + com else None, "%.0f%%"), fmt(rb)))
    return ("Stages (GL clock, ms): the sprite splat and thickness passes (vertex and fragment work) against the "
            "march, normals and filter passes (compute shaders), and the read back (wall):\n\n"
            + table(("particles", "size", "splat + thickness", "march + normals + filter", "sprite share", "read back"),
                    body, "xiao2017_stages"))


def sprite_ms(st):
    """The GL-clock ms of the sprite passes (raster or compute) among a cell's stage medians."""
    return sum(st.get(x, (0, 0))[1] or 0 for x in RASTER + SPLAT_COMPUTE)


def xiao_splat(rs):
    """raycast_pca with its sprite passes on the raster and on the compute splatter, per cell."""
    if not any(splat_path(r["variant"]) == "compute" for r in rs):
        return ""
    key = lambda r: (int(r["particles"]), int(r["size"]), splat_path(r["variant"]))
    fr, st = frames(rs, T1_STAGES, key), stage_medians(rs, key)
    body, fast, with_paper = [], 0, 0
    for (n, size) in sorted({(n, s) for n, s, _ in fr}):
        ras, com = st.get((n, size, "raster"), {}), st.get((n, size, "compute"), {})
        gr, gc = fr.get((n, size, "raster"), (None, None))[1], fr.get((n, size, "compute"), (None, None))[1]
        p = paper_xiao(n, size)
        if p and gc:
            with_paper += 1
            fast += gc <= p * 1e3
        body.append((n, size, fmt(sprite_ms(ras) if ras else None), fmt(sprite_ms(com) if com else None),
                     ratio(sprite_ms(ras) if ras else None, sprite_ms(com) if com else None), fmt(gr), fmt(gc),
                     fmt(p * 1e3 if p else None), ratio(p * 1e3 if p else None, gc)))
    big = [k for k in fr if k[2] == "compute" and paper_xiao(k[0], k[1]) and k[0] > 100e6 and k[1] == 1024]
    target = ("; the 142M-particle cell at 1024^2 takes %s ms (the target: at most 157 ms, 5x faster than the paper's "
              "784 ms)" % fmt(fr[big[0]][1]) if big else "")
    verdict = (" With `splat=compute`, %d of the %d cells the paper has are at least as fast as its GTX 970%s." % (
        fast, with_paper, target) if with_paper else "")
    return ("\nThe sprite passes on the raster (`splat=raster`, the paper's pipeline) and on the compute splatter "
            "(`splat=compute`, docs/DESIGN.md \"The compute splatter\"; the same G-buffer), GL clock, ms: the sprite "
            "stages (splat and thickness, or splat_compute and thickness_compute), raster over compute, and the "
            "frame of each path as in the first table.%s\n\n" % verdict
            + table(("particles", "size", "sprites raster", "sprites compute", "raster / compute", "frame raster",
                     "frame compute", "paper ms (GTX 970)", "paper / compute"), body, "xiao2017_splat"))


def variant(v):
    """(anisotropy, filter) of a render_bench variant string."""
    kv = dict(x.split("=", 1) for x in v.replace("aniso_ssf.", "").split(";") if "=" in x)
    return kv.get("anisotropy", "?"), kv.get("filter", "?")


def xu(d):
    everything = rows(d, "xu2022_fig9.csv")
    rs = raster_rows(everything)
    if not rs:
        return "No xu2022 rows.\n"
    fr = frames(rs, F9_STAGES, lambda r: (int(r["particles"]),) + variant(r["variant"]))
    g = {k: v[1] for k, v in fr.items()}
    ns = sorted({k[0] for k in fr})
    body = [(n, f, fmt(g.get((n, "off", f))), fmt(g.get((n, "on", f))), ratio(g.get((n, "on", f)), g.get((n, "off", f))),
             fmt(fr.get((n, "on", f), (None,))[0])) for n in ns for f in FILTERS if (n, "on", f) in fr]
    out = XU_COLUMNS + table(("particles", "filter", "anisotropy off ms (GL clock)", "on ms (GL clock)", "on / off",
                              "on ms (wall, + read back)"), body, "xu2022_fig9")
    return (out + "\n" + EXCLUDED % "the anisotropy's neighbour search runs on the GPU in every frame (its pass is "
            "in the frame), the grid it searches is built once per set" + "\n" + setup_table(rs, "xu2022_setup") + "\n"
            + xu_statements(rs, g, ns) + xu_splat(everything))


XU_COLUMNS = ("Columns: *off* and *on (GL clock)* are the sums of aniso_ssf's GL stages (the anisotropy pass when on, "
              "splat, filter, normals, thickness) on the GL clock, without the read back of the G-buffer, the shading "
              "(on the CPU, not timed here) and the once-per-set work below; *on (wall)* adds the read back, on the "
              "wall clock. The paper's Fig. 9 plots the frame rate of its whole pipeline, shading included.\n\n")


def xu_statements(rs, g, ns):
    """The paper's three statements about Fig. 9 against our cells (GL clock)."""
    ratios = [g[(n, "on", f)] / g[(n, "off", f)] for n in ns for f in FILTERS
              if g.get((n, "on", f)) and g.get((n, "off", f))]
    st = stage_medians(rs, lambda r: (int(r["particles"]),) + variant(r["variant"]))
    an = [st.get((n, "on", "narrow"), {}).get("anisotropy", (None, None))[1] for n in ns]
    nr = [g.get((n, "on", "narrow")) for n in ns]
    on, off = st.get((ns[-1], "on", "narrow"), {}), st.get((ns[-1], "off", "narrow"), {})
    extra = ", ".join("%s %s ms" % (x, fmt((on.get(x, (0, 0))[1] or 0) - (off.get(x, (0, 0))[1] or 0)))
                      for x in ("anisotropy", "splat", "thickness", "filter"))
    last = {a: [g[(ns[-1], a, f)] for f in FILTERS if g.get((ns[-1], a, f))] for a in ("on", "off")}
    spread = {a: 100 * (max(v) / min(v) - 1) if v else float("nan") for a, v in last.items()}
    lines = ["The paper (RTX 3060) gives Fig. 9 as a plot of frame rates without numbers in its text, so the comparison "
             "is with its three statements:", ""]
    if ratios:
        lines.append("- *Anisotropy barely affects the pipeline's cost*: on / off is %.2f to %.2f over the %d cells "
                     "(median %.2f); at %d particles %.2f to %.2f. The anisotropy pass itself (narrow-range, GL clock) "
                     "takes %s ms from %d to %d particles." % (
                         min(ratios), max(ratios), len(ratios), statistics.median(ratios), ns[-1],
                         min(g[(ns[-1], "on", f)] / g[(ns[-1], "off", f)] for f in FILTERS if (ns[-1], "on", f) in g),
                         max(g[(ns[-1], "on", f)] / g[(ns[-1], "off", f)] for f in FILTERS if (ns[-1], "on", f) in g),
                         " -> ".join(fmt(a) for a in an), ns[0], ns[-1]))
        lines.append("- Where anisotropy's extra time goes at %d particles (narrow-range, on minus off, GL clock): %s: "
                     "the pass that computes the ellipsoids, then the larger ellipsoid sprites." % (ns[-1], extra))
    steps = ["%.1fx the particles %sx the time" % (b / a, ratio(y, x, "%.2f")) for a, b, x, y in zip(ns, ns[1:], nr, nr[1:])
             if x and y]
    if steps:
        lines.append("- *Narrow-range keeps the time almost linear in the particle count*: with anisotropy on, %s ms "
                     "from %d to %d particles; step by step %s. A fixed cost (the sprites' raster work at 1024^2) "
                     "dominates the small sets. At %d particles the five filters' frames are within %.1f%% of each "
                     "other with anisotropy on (%.1f%% off): the growth is the sprites' and the anisotropy's, the "
                     "same under every filter." % (
                         " -> ".join(fmt(x) for x in nr), ns[0], ns[-1], ", ".join(steps), ns[-1], spread["on"],
                         spread["off"]))
    cf = [g[(n, "on", "curvature")] / g[(n, "on", "gaussian")] for n in ns
          if g.get((n, "on", "curvature")) and g.get((n, "on", "gaussian"))]
    if cf:
        lines.append("- *Curvature flow's time grows with its iterations* (the paper calls it time-consuming): the "
                     "iteration count was not swept here. At the shipped 80 iterations, with anisotropy on, it takes "
                     "%s times the Gaussian's frame (2 iterations) from %d to %d particles: at most %.0f%% more, so "
                     "on this GPU its iterations cost little." % (
                         ", ".join("%.2f" % x for x in cf), ns[0], ns[-1], 100 * (max(cf) - 1)))
    return "\n".join(lines) + "\n"


def xu_splat(rs):
    """aniso_ssf (narrow-range filter) with its sprite passes on the raster and on the compute splatter."""
    if not any(splat_path(r["variant"]) == "compute" for r in rs):
        return ""
    rs = [r for r in rs if variant(r["variant"])[1] == "narrow"]
    key = lambda r: (int(r["particles"]), variant(r["variant"])[0], splat_path(r["variant"]))
    fr, st = frames(rs, F9_STAGES, key), stage_medians(rs, key)
    body = []
    for (n, a) in sorted({(n, a) for n, a, _ in fr}):
        ras, com = st.get((n, a, "raster"), {}), st.get((n, a, "compute"), {})
        gr, gc = fr.get((n, a, "raster"), (None, None))[1], fr.get((n, a, "compute"), (None, None))[1]
        body.append((n, a, fmt(sprite_ms(ras) if ras else None), fmt(sprite_ms(com) if com else None),
                     ratio(sprite_ms(ras) if ras else None, sprite_ms(com) if com else None), fmt(gr), fmt(gc),
                     ratio(gc, gr)))
    n = max(k[0] for k in fr)
    half = ["%s (anisotropy %s)" % (ratio(fr.get((n, a, "compute"), (0, None))[1], fr.get((n, a, "raster"), (0, None))[1]),
                                     a) for a in ("off", "on")]
    return ("\nThe sprite passes on the raster (`splat=raster`) and on the compute splatter (`splat=compute`), "
            "narrow-range filter, GL clock, ms: the sprite stages, raster over compute, and each path's frame. At %d "
            "particles the compute frame over the raster's is %s (the target: at most 0.5).\n\n" % (n, ", ".join(half))
            + table(("particles", "anisotropy", "sprites raster", "sprites compute", "raster / compute",
                     "frame raster", "frame compute", "compute / raster"), body, "xu2022_splat"))


def inacio_cells(rs):
    """(requested count, path) -> dict of stage medians over the timed frames (ms): the paper's
    columns as results/inacio2010/README.md maps them, GL-clock variants with the suffix _gl."""
    per = defaultdict(lambda: defaultdict(list))
    for r in rs:
        per[(int(r["particles_requested"]), r["path"])][(r["table"], r["stage"])].append(r)
    cells = {}
    for k, st in per.items():
        m = lambda t, s, col="ms": med([num(r[col]) for r in st[(t, s)]])
        first = st[("sim", "simulation")][0]
        cells[k] = {"particles": int(first["particles"]), "all": int(first["particles"]) + int(first["boundary"]),
                    "steps": med([num(r["steps"]) for r in st[("sim", "simulation")]]),
                    "sim": m("sim", "simulation"), "sim_gl": m("sim", "simulation", "gpu_ms"),
                    "volume": m("I", "volume"), "volume_gl": m("I", "volume", "gpu_ms"),
                    "ray": (m("I", "faces") or 0) + (m("I", "march") or 0),
                    "ray_gl": (m("I", "faces", "gpu_ms") or 0) + (m("I", "march", "gpu_ms") or 0),
                    "render_I": sum(m("I", s) or 0 for s in ("readback", "renormalize", "shade")),
                    "spheres": sum(m("II", s) or 0 for s in ("upload", "splat", "readback", "renormalize", "shade")),
                    "splat_gl": m("II", "splat", "gpu_ms")}
    return cells


def inacio(d):
    rs = rows(d, "inacio2010_tables.csv")
    if not rs:
        return "No inacio2010 rows.\n"
    c = inacio_cells(rs)
    return inacio_table1(c) + "\n" + inacio_table2(c) + "\n" + inacio_trends(c) + "\n" + marches(d)[0]


def march_frames(rs):
    """(requested count, path) -> table (I, I_slice) -> the march's timed frames, on the GL
    clock where every frame has it, else on the wall clock."""
    per = defaultdict(lambda: defaultdict(list))
    for r in rs:
        if r["table"] in ("I", "I_slice") and r["stage"] == "march":
            per[(int(r["particles_requested"]), r["path"])][r["table"]].append(r)
    out = {}
    for k, t in per.items():
        if t["I"] and t["I_slice"]:
            col = "gpu_ms" if all(num(r["gpu_ms"]) for r in t["I"] + t["I_slice"]) else "ms"
            out[k] = {n: [num(r[col]) for r in t[n]] for n in ("I", "I_slice")}
    return out


def marches(d):
    """The bound of issue 52 on one run: volume_raycast's march over the layered volume (Table
    I) and over the slice-built volume of the same particles (I_slice) do the same work on the
    same grid (tests/test_volume_raycast_builds.c: the same hits within a grid spacing), so
    their medians must agree within the run's spread: the largest max / min of one cell's
    timed frames of either march. (text, the cells outside it)."""
    fr = march_frames(rows(d, "inacio2010_tables.csv"))
    if not fr:
        return "", []
    dm = [num(r["gpu_ms_median"]) for r in rows(d, "demo_timings.csv")
          if r["method"] == "volume_raycast" and r["variant"] == "" and r["stage"] == "march"]
    demo_note = (" For scale: the demo's march (the layered build, %s, grid 256, every ray marched to the box's "
                 "exit for the thickness) takes %.2f ms on the GL clock in this run; Table I's march stops at the "
                 "surface, on fewer pixels and a coarser grid (run.sh: 512^2 and 128 in full mode)." % (
                     demo_size(d), dm[0])) if dm and dm[0] else ""
    spread = max(max(v) / min(v) for t in fr.values() for v in t.values() if min(v) > 0)
    body, bad = [], []
    for k in sorted(fr):
        a, b = med(fr[k]["I"]), med(fr[k]["I_slice"])
        q = b / a if a else float("inf")
        ok = 1 / spread <= q <= spread
        if not ok:
            bad.append(k)
        body.append((k[0], k[1], fmt(a, "%.3f"), fmt(b, "%.3f"), fmt(q, "%.2f"), "yes" if ok else "**no**"))
    text = ("The march on both volumes (issue 52): the same march shader over the layered volume (Table I) and "
            "over the slice-built volume of the same particles (`I_slice`), medians of the timed frames (ms, "
            "the GL clock where every frame has it). The two do the same work (the same grid, the same hits: "
            "tests/test_volume_raycast_builds.c), so they must agree within the run's spread, the largest "
            "max / min of one cell's frames of either march: %.2f here.%s %s\n\n" % (
                spread, demo_note, "Every cell agrees." if not bad else
                "%d of %d cells do not (experiments/gpu/README.md, \"The march on both volumes\", says why)."
                % (len(bad), len(fr))))
    return text + table(("particles", "path", "march, layered", "march, slice-built", "slice / layered",
                         "within the spread"), body, "inacio2010_marches"), bad


def inacio_table1(c):
    body = []
    for (n, path), x in sorted(c.items()):
        tot = x["sim"] + x["volume"] + x["ray"] + x["render_I"]
        p = INACIO_I.get((n, path))
        body.append((x["particles"], path, fmt(x["steps"], "%.0f"), fmt(x["sim"]), fmt(x["sim"] / x["steps"], "%.2f"),
                     fmt(x["volume"]), fmt(x["ray"]), fmt(x["render_I"]), fmt(tot), fmt(100 * x["sim"] / tot, "%.0f%%"),
                     fmt(p[0] * 1e3 if p else None), fmt(100 * p[0] / sum(p) if p else None, "%.0f%%")))
    return ("Table I analogue (ray casting), ms per frame of 1/60 s, wall clock, medians of the timed frames. "
            "Columns: *steps* is how many adaptive steps the simulator takes for the frame (one step of 0.01 s "
            "explodes: results/inacio2010, Fig. 7), *simulation, frame* all of them and *simulation, one step* "
            "their mean, which is what the paper's one step of 0.01 s per frame compares with. *read back + "
            "shading* is the G-buffer's read back and the shared shading on the CPU, where the paper's rendering "
            "column is the display of its image (0.5 to 5.6 ms). *total* and *simulation share* include every step "
            "and the read back and shading, so the share is not the paper's like for like: that is the GL-clock "
            "share of one step in the last table.\n\n"
            + table(("particles", "path", "steps", "simulation, frame", "simulation, one step", "volume", "ray casting",
                     "read back + shading", "total", "simulation share", "paper simulation (one step)",
                     "paper simulation share"), body, "inacio2010_table1"))


def inacio_table2(c):
    body = []
    for (n, path), x in sorted(c.items()):
        p = INACIO_II.get((n, path))
        tot = x["sim"] + x["spheres"]
        body.append((x["particles"], path, fmt(x["steps"], "%.0f"), fmt(x["sim"]), fmt(x["sim"] / x["steps"], "%.2f"),
                     fmt(x["spheres"]), fmt(tot), fmt(100 * x["sim"] / tot, "%.0f%%"), fmt(p[0] * 1e3 if p else None),
                     fmt(p[1] * 1e3 if p else None), fmt(100 * p[0] / sum(p) if p else None, "%.0f%%")))
    return ("Table II analogue (spheres), the same frames. Columns: *spheres* is the particle upload, the sprite "
            "splat, the read back and the shared shading on the CPU (wall clock), where the paper's rendering is its "
            "sphere drawing on the GPU; *total* and *simulation share* include every step of the frame, the "
            "paper's one step.\n\n"
            + table(("particles", "path", "steps", "simulation, frame", "simulation, one step", "spheres", "total",
                     "simulation share", "paper simulation (one step)", "paper rendering", "paper simulation share"),
                    body, "inacio2010_table2"))


def inacio_trends(c):
    body = []
    for n in sorted({n for n, _ in c}):
        cpu, gpu = c.get((n, "cpu")), c.get((n, "gpu"))
        if not (cpu and gpu):
            continue
        pi, pc, pg = INACIO_I.get((n, "gpu")), INACIO_II.get((n, "cpu")), INACIO_II.get((n, "gpu"))
        vis = gpu["volume_gl"] + gpu["ray_gl"] if gpu["volume_gl"] is not None else None
        sim, step = gpu["sim_gl"], gpu["sim_gl"] / gpu["steps"] if gpu["sim_gl"] and gpu["steps"] else None
        share = lambda t: fmt(100 * t / (t + vis) if t is not None and vis else None, "%.0f%%")
        body.append((gpu["particles"], gpu["all"], ratio(cpu["sim"], gpu["sim"], "%.1f"),
                     ratio(pc[0], pg[0], "%.1f") if pc and pg else "", share(sim), share(step),
                     fmt(100 * pi[0] / sum(pi) if pi else None, "%.0f%%"), ratio(vis, gpu["splat_gl"], "%.1f"),
                     ratio(sum(pi[1:]), pg[1], "%.1f") if pi and pg else ""))
    return ("Ratios and trends. *CPU / GPU simulation*: the CPU path (C + OpenMP on the node's cores) against the GPU "
            "path (compute shaders), wall clock, per frame, which is also per step (both paths take the same steps); "
            "the paper's from Table II (Table I "
            "lacks its 8192 GPU row). The CPU path runs its loops on one thread below 16,384 particles, boundary "
            "included (FS_SPH_PARALLEL_MIN, common/sph/sph_cpu.c, set on a 2-core machine), so the smaller rows compare "
            "one CPU core with the GPU. *GPU-path simulation share* (Fig. 5): the simulation's GL-clock time over it "
            "plus volume and ray casting (GL clock), leaving out our read back and CPU shading; once for our frame of "
            "1/60 s (*frame*: all its steps) and once for one step per frame (*one step*), as the paper's frame has; "
            "the paper's, of one step, from Table I, whose frame also holds its display (0.5 to 5.6 ms). *Ray "
            "casting / spheres*, GPU path: volume + ray casting against the sphere splat, both on the GL "
            "clock; the paper's: volume + ray casting + rendering (Table I) against its whole sphere rendering (Table II), "
            "so ours leaves the spheres' upload, read back and shading out of the denominator. The paper's GPU-path "
            "volume is 128x512x512, ours 128 points along the longest axis on both paths.\n\n"
            + table(("particles", "with boundary", "CPU / GPU simulation", "paper CPU / GPU",
                     "GPU-path simulation share, frame", "share, one step", "paper share (one step)",
                     "ray casting / spheres", "paper ray casting / spheres"), body, "inacio2010_trends", keys=1))


def iwasaki(d):
    rs = rows(d, "iwasaki2006_density_grid.csv")
    if not rs:
        return "No iwasaki2006 rows.\n"
    cell = defaultdict(list)  # (label, particles, res) -> rows: one label per thread setting
    for r in rs:
        cell[(r["label"], int(r["particles"]), int(r["res"]))].append(r)
    body = []
    for k in sorted(cell, key=lambda k: (k[1], k[2], k[0])):
        ex = [r for r in cell[k] if r["method"] == "exact_cpu"]
        sp = [r for r in cell[k] if r["method"] == "slice_splat"]
        e, w = med([num(r["ms"]) for r in ex]), med([num(r["ms"]) for r in sp])
        g = med([num(r["gpu_ms"]) for r in sp])
        l2 = max(num(r["rel_l2_vs_exact"]) or 0 for r in sp) if sp else None
        body.append((k[1], k[2], ex[0]["threads"] if ex else "", fmt(e), fmt(w), fmt(g), ratio(e, w, "%.1f"),
                     fmt(l2, "%.3g")))
    body.append(("about 210,000", 256, "1 (Pentium 4)", "about 80000", "910", "", "88", "1.9%"))
    return ("The density grid: iwasaki2006's slice splatting on the GL against the exact CPU sum (C + OpenMP), "
            "medians; the last row is the paper's (GeForce 6800 GT, its section 6). The slice splat's time spans "
            "its host work too (clustering the particles, the upload, the read back), and its GL clock brackets the "
            "whole stage, so the two clocks agree and neither isolates the GPU's share. CPU / GL sets the GPU against the CPU threads of the row: "
            "the paper's 88x is against one CPU core.\n\n"
            + table(("particles", "res", "CPU threads", "exact CPU ms", "slice splat ms (wall)",
                     "slice splat ms (GL clock)", "CPU / GL", "rel. L2 against exact"), body, "iwasaki2006_density_grid"))


SURFEL_RENDER = ("caustics", "visibility", "blend", "normalize", "thickness")


def demo_size(d):
    """The demo's image size, from its cell's name in status.csv (dam_break_SIZE)."""
    cells = [r["cell"] for r in rows(d, "status.csv") if r["step"] == "demo_compare"]
    size = cells[0].rsplit("_", 1)[-1] if cells else "?"
    return "%s^2" % size


def demo(d):
    rs = rows(d, "demo_timings.csv")
    if not rs:
        return "No demo rows.\n"
    metrics = {(r["method"], r["variant"]): r for r in rows(d, "demo_metrics.csv")}
    body = []
    for r in (r for r in rs if r["stage"] == "total"):
        st = [x for x in rs if (x["method"], x["variant"]) == (r["method"], r["variant"])]
        gl = [num(x["gpu_ms_median"]) for x in st if num(x["gpu_ms_median"]) is not None]
        rb = [num(x["ms_median"]) for x in st if x["stage"] == "readback"]
        m = metrics.get((r["method"], r["variant"] if r["variant"] != "ground truth" else ""), {})
        body.append((r["method"], r["variant"], fmt(sum(gl) if gl else None), fmt(num(r["ms_median"])),
                     fmt(rb[0] if rb else None), r["renderer"], m.get("mask_iou", ""), m.get("normal_mean_deg", "")))
    sr = [num(x["gpu_ms_median"]) for x in rs if x["method"] == "surfels" and x["stage"] in SURFEL_RENDER]
    srb = [num(x["ms_median"]) for x in rs if x["method"] == "surfels" and x["stage"] == "readback"]
    out = DEMO_COLUMNS + table(("method", "variant", "GL stages ms (GL clock)", "total ms (wall)", "read back ms",
                                "renderer", "mask IoU", "normal error deg"), body, "demo")
    if sr and None not in sr and srb:
        out += ("\nsurfels' rendering stages (%s; the density grid and the surfel extraction excluded, as the paper "
                "times them apart) take %.1f ms on the GL clock here, on the bundled dam break at %s, and %.1f ms "
                "with the read back of the G-buffer (%.1f ms), before the shading on the CPU, which is not timed; "
                "iwasaki2006 renders its 61,500-77,000 surfels at 512^2 in about 39 ms (25.5 fps, GeForce 6800 GT, "
                "Figs. 6 and 7), its shading on the GPU included.\n" % (
                    ", ".join(SURFEL_RENDER), sum(sr), demo_size(d), sum(sr) + srb[0], srb[0]))
    return out + demo_splat(d)


def demo_splat(d):
    """The sprite-splatting methods of the demo with splat=compute against the plain demo's raster."""
    com = rows(d, "demo_splat_timings.csv")
    if not com:
        return ""
    ras, metrics = rows(d, "demo_timings.csv"), {r["method"]: r for r in rows(d, "demo_splat_metrics.csv")}

    def cell(rs, method):
        st = {x["stage"]: (num(x["ms_median"]), num(x["gpu_ms_median"])) for x in rs if x["method"] == method}
        return sprite_ms(st) if st else None, st.get("total", (None,))[0]

    body = []
    for m in sorted({r["method"] for r in com if r["method"] != "reference"}):
        (sr, tr), (sc, tc) = cell([r for r in ras if r["variant"] == ""], m), cell(com, m)
        body.append((m, fmt(sr), fmt(sc), ratio(sr, sc), fmt(tr), fmt(tc), metrics.get(m, {}).get("mask_iou", "")))
    return ("\nThe sprite-splatting methods again with `splat=compute` (`demo_splat_timings.csv`): the sprite stages "
            "on the GL clock (ms) and the frame on the wall clock, raster (the table above) and compute, and the "
            "compute render's mask IoU against the reference:\n\n"
            + table(("method", "sprites raster", "sprites compute", "raster / compute", "total raster (wall)",
                     "total compute (wall)", "mask IoU (compute)"), body, "demo_splat", keys=1))


DEMO_COLUMNS = ("Columns: *GL stages* is the sum of the method's stages that have a GL clock (surfels' density grid "
                "included, its surfel extraction on the CPU not); *total* is every stage of the timed render on the "
                "wall clock, the read back and the CPU stages included, without the shared shading, which compare "
                "does not time; the reference's ground-truth row is one render (not a median), its shading included.\n\n")


ABOUT_GPU = """## What this GPU is

The H200 is a data-centre GPU built on the GH100 die of the H100. NVIDIA's white paper "NVIDIA
H100 Tensor Core GPU Architecture" (2022) says that only two TPCs of the H100 are graphics-capable
(able to run vertex, geometry and pixel shaders), while compute shaders run on all its SMs. So
these are timings on a real GPU through NVIDIA's GL driver, but not on a graphics GPU like the
papers' GTX 970, RTX 3060, GeForce 9800M GS or GeForce 6800 GT: a stage that rasterises (sprite
splatting, the density slices, the layered volume) would be expected to run faster on one of
those, by an amount this run cannot measure. %s
The read back of the G-buffer to the host (fluidsurf shades on the CPU, after it) is large on
this node. The papers shade on their GPUs inside the frames they time; most frames here leave the
shading out, and each table says which of its columns include the read back and the shading.
"""


def raster_evidence(d):
    """A sentence from the CSVs: a small raster pass against a large compute pass."""
    xu_rs = [r for r in rows(d, "xu2022_fig9.csv") if r["run"] != "0" and "anisotropy=off" in r["variant"]]
    t1 = [r for r in raster_rows(rows(d, "xiao2017_table1.csv")) if r["run"] != "0"]
    if not xu_rs or not t1:
        return ""
    n = min(int(r["particles"]) for r in xu_rs)
    splat = med([num(r["gpu_ms"]) for r in xu_rs if int(r["particles"]) == n and r["stage"] == "splat"])
    big, size = max(int(r["particles"]) for r in t1), max(int(r["size"]) for r in t1)
    march = med([num(r["gpu_ms"]) for r in t1 if (int(r["particles"]), int(r["size"]), r["stage"]) == (big, size, "march")])
    return ("In this run a raster pass of %d sphere sprites (xu2022's splat at %s, anisotropy off) takes %s ms on "
            "the GL clock, while raycast_pca's march, a compute pass over %d^2 pixels through %d particles, takes "
            "%s ms." % (n, F9_SIZE_LABEL, fmt(splat), size, big, fmt(march)))


F9_SIZE_LABEL = "1024^2"


def header(d):
    env = machine(d)
    demo_cell = [r["cell"] for r in rows(d, "status.csv") if r["step"] == "demo_compare"]
    return ("# The papers' speed tables on a GPU\n\n"
            "<!-- generated by experiments/gpu/report.py from the CSVs beside it; do not edit: "
            "python3 experiments/gpu/report.py results/gpu > results/gpu/README.md -->\n\n"
            "One run of `experiments/gpu/device.sh` (`experiments/gpu/run.sh` from the lean pack, EGL) on a lent "
            "machine, %s mode, %s.\n\n"
            "| | |\n|---|---|\n| GL_RENDERER | %s |\n| GL_VERSION | %s |\n| GPU | %s, driver %s, %s |\n"
            "| clocks at the start | SM %s (max %s), memory %s (max %s), power limit %s |\n| CPU | %s |\n"
            "| fluidsurf | %s |\n| provenance | %s |\n\n"
            "Files: `env.csv` (the machine), `status.csv` (every cell, its time and exit status), one CSV per "
            "step (`xiao2017_table1.csv`, `xu2022_fig9.csv`, `inacio2010_tables.csv`, "
            "`iwasaki2006_density_grid.csv`, `demo_timings.csv` and `demo_metrics.csv` of `fluidsurf compare` on "
            "the bundled dam break, cell %s), `logs/` (the steps' stderr), `run.log`, `demo_panel_small.png` (the "
            "demo's panel as the GPU drew it, scaled down; the lean build writes no labels: reference, spheres, "
            "raycast_pca, aniso_ssf, surfels, volume_raycast, with the error maps under them), `tables.csv` (every "
            "number of this README's tables, unrounded, for prose that cites them). Each CSV starts with "
            "the provenance line of the commit the packed binaries were built from.\n\n" % (
                env.get("mode", "?"), env.get("date", "?"), env.get("gl_renderer", "?").strip('"'),
                env.get("gl_version", "?").strip('"'), env.get("gpu", "no nvidia-smi").strip('"'),
                env.get("driver", "?"), env.get("gpu_memory", "?"), env.get("clock_sm", "?"),
                env.get("clock_max_sm", "?"), env.get("clock_mem", "?"), env.get("clock_max_mem", "?"),
                env.get("power_limit", "?"), env.get("cpu", "?").strip('"'), env.get("fluidsurf", "?").strip('"'),
                provenance(d, "env.csv"), ", ".join(demo_cell) or "none"))


def about(d):
    """What the renderer is: the note on Hopper's graphics, or the quick mode's warning."""
    env = machine(d)
    if env.get("mode") == "quick":
        return "## The renderer\n\nQuick mode (small sizes, CI's rehearsal): these timings say nothing about a GPU.\n"
    r = env.get("gl_renderer", "").lower()
    return ABOUT_GPU % raster_evidence(d) if ("h200" in r or "h100" in r) else ""


def demo_gl(rs):
    """(method, variant) -> the sum of its stages' GL-clock medians in a demo_timings.csv."""
    out = defaultdict(float)
    for x in rs:
        g = num(x["gpu_ms_median"])
        if g is not None:
            out[(x["method"], x["variant"])] += g
    return out


def repeat(d):
    """A second run in DIR/repeat (run.sh's step repeat: another call, another machine maybe):
    the ratio of its GL-clock frame times to this run's, per cell, for the render tables it
    repeats (xiao2017's at one size, xu2022's when a whole run was repeated) and the demo."""
    r = os.path.join(d, "repeat")
    if not os.path.isdir(r):
        return ""
    env = machine(r)
    body = []
    for name, stages, key in (("xiao2017_table1.csv", T1_STAGES, lambda x: (int(x["particles"]), int(x["size"]))),
                              ("xu2022_fig9.csv", F9_STAGES, lambda x: (int(x["particles"]), x["variant"]))):
        a, b = frames(raster_rows(rows(d, name)), stages, key), frames(raster_rows(rows(r, name)), stages, key)
        q = sorted(b[k][1] / a[k][1] for k in a if k in b and a[k][1] and b[k][1])
        if q:
            body.append((name, len(q), "%.2f" % statistics.median(q), "%.2f" % q[0], "%.2f" % q[-1]))
    a, b = demo_gl(rows(d, "demo_timings.csv")), demo_gl(rows(r, "demo_timings.csv"))
    q = sorted(b[k] / a[k] for k in a if k in b and a[k] and b[k])
    if q:
        body.append(("demo_timings.csv", len(q), "%.2f" % statistics.median(q), "%.2f" % q[0], "%.2f" % q[-1]))
    return ("## Repeatability\n\nThe same script run again (`repeat/`: %s, %s, %s), each cell's GL-clock frame "
            "time over this run's:\n\n" % (env.get("date", "?"), env.get("gl_renderer", "?").strip('"'),
                                             provenance(r, "env.csv"))
            + table(("CSV", "cells", "median repeat / first", "lowest", "highest"), body))


def report(d):
    del CELLS[:]
    out = [header(d), about(d)]
    for title, f in (("xiao2017 Table 1 (raycast_pca; also Fig. 9)", xiao), ("xu2022 Fig. 9 (aniso_ssf)", xu),
                     ("inacio2010 Tables I and II (the simulator, volume_raycast, spheres; also Fig. 5)", inacio),
                     ("iwasaki2006 section 4: the density grid (Fig. 8's 88x)", iwasaki),
                     ("The demo comparison (every GL method and the CPU reference)", demo)):
        out.append("## %s\n\n%s" % (title, f(d)))
    again = repeat(d)
    if again:
        out.append(again)
    bad = [r for r in rows(d, "status.csv") if r["exit"] != "0"]
    if bad:
        out.append("## Cells that did not finish\n\n" + table(("step", "cell", "exit", "note"),
                                                              [(r["step"], r["cell"], r["exit"], r["note"]) for r in bad]))
    return "\n".join(out)


def tables_csv(d):
    """tables.csv: every number of report(d)'s tables, unrounded, under the run's provenance."""
    report(d)
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    out.write("# experiments/gpu/report.py: the numbers of README.md's tables; %s\n" % provenance(d, "env.csv"))
    w.writerow(("table", "key", "sub", "column", "value"))
    w.writerows((t, k, s, c, "%.10g" % v) for t, k, s, c, v in CELLS)
    return out.getvalue()


def stale(d, name, text, how):
    """An error when DIR/name is missing or differs from text, else None."""
    path = os.path.join(d, name)
    if not os.path.isfile(path):
        return "report.py: %s: missing (write it with %s)" % (path, how)
    with open(path) as f:
        if f.read() != text:
            return "report.py: %s is stale: regenerate it with %s" % (path, how)
    return None


def bounds(d):
    """--bounds: exit 1 when the run breaks a bound the next GPU run must meet (issue 52: the
    two marches agree within the run's spread)."""
    if not march_frames(rows(d, "inacio2010_tables.csv")):
        print("report.py: %s: no march rows of inacio2010's Table I (the step did not run here): nothing to bound" % d)
        return
    bad = marches(d)[1]
    if bad:
        sys.exit("report.py: %s: the march over the slice-built volume and over the layered one differ beyond the "
                 "run's spread in %d cell(s): %s" % (d, len(bad), ", ".join("%d %s" % k for k in bad)))
    print("report.py: %s: the two marches agree within the run's spread" % d)


def main():
    args = sys.argv[1:]
    mode = args.pop(0) if args and args[0] in ("--check", "--tables", "--bounds") else None
    d = (args or ["results/gpu"])[0]
    if not os.path.isfile(os.path.join(d, "env.csv")):
        sys.stderr.write("report.py: %s: no env.csv: not a folder of experiments/gpu/run.sh\n" % d)
        sys.exit(2)
    if mode is None:
        sys.stdout.write(report(d))
        return
    if mode == "--tables":
        sys.stdout.write(tables_csv(d))
        return
    if mode == "--bounds":
        bounds(d)
        return
    errs = [e for e in (stale(d, "README.md", report(d), "python3 experiments/gpu/report.py %s > %s/README.md" % (d, d)),
                        stale(d, "tables.csv", tables_csv(d),
                              "python3 experiments/gpu/report.py --tables %s > %s/tables.csv" % (d, d))) if e]
    if errs:
        sys.exit("\n".join(errs))
    print("report.py: %s/README.md and tables.csv match its CSVs" % d)


if __name__ == "__main__":
    main()
