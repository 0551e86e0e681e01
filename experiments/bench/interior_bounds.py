#!/usr/bin/env python3
"""How tight the reference's sub-cell lower bounds of phi are inside a liquid
(methods/reference/README.md, "Sub-cell bounds"). A lattice of spacing 2r with
V = (2r)^3, cubic spline, H = 4r (the defaults: phi ~ 1 inside, iso 0.6). For
boxes of edge e centred at 20 seeded points near the lattice's centre:
  monotone: sum_j V W(farthest distance from p_j to the box)   (reference_bounds.c)
  taylor:   phi(c) - |grad phi(c)|_1 e/2 - M hd^2 / 2         (reference_interior.c)
A box is proven inside when its lower bound is at least iso.
Writes results/bench/interior_bounds.csv. Standard library only."""
import math, os, random, subprocess, sys

R, H, ISO = 1.0, 4.0, 0.6
S = 8.0 / (math.pi * H ** 3)
V = (2 * R) ** 3

def w(d):
    q = d / H
    if q <= 0.5: return S * (6 * q ** 3 - 6 * q ** 2 + 1)
    if q < 1: return 2 * S * (1 - q) ** 3
    return 0.0

def wd_over_d(d):  # W'(d) / d
    q = d / H
    if q <= 0.5: return S / H ** 2 * (18 * q - 12)
    if q < 1: return -6 * S / H ** 2 * (1 - q) ** 2 / q
    return 0.0

def k2_major(dmin):  # majorant of max(|W''|, |W'/d|) at distances >= dmin
    return 12 * S / H ** 2 * max(0.0, 1 - dmin / H)

def bounds(c, e, pts):
    hd = e * math.sqrt(3) / 2
    mono = phi = m = 0.0
    g = [0.0, 0.0, 0.0]
    for p in pts:
        dx = [c[a] - p[a] for a in range(3)]
        far = math.sqrt(sum((abs(x) + e / 2) ** 2 for x in dx))
        mono += V * w(far)
        d = math.sqrt(sum(x * x for x in dx))
        if d >= H + hd: continue
        phi += V * w(d)
        for a in range(3): g[a] += V * wd_over_d(d) * dx[a]
        m += V * k2_major(max(0.0, d - hd))
    taylor = phi - sum(abs(x) for x in g) * e / 2 - m * hd * hd / 2
    return mono, taylor, phi

def study_commit():
    """experiments/lib.sh's study_commit: the commit and whether the tree outside results/ differs."""
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")
    try:
        c = subprocess.run(["git", "-C", root, "rev-parse", "--short=10", "HEAD"], capture_output=True, text=True, check=True).stdout.strip()
        d = subprocess.run(["git", "-C", root, "diff", "--quiet", "HEAD", "--", ".", ":!results"]).returncode != 0
    except (OSError, subprocess.CalledProcessError):
        return "commit=unknown; dirty=1"
    return "commit=%s; dirty=%d" % (c, d)

def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "../../results/bench/interior_bounds.csv")
    rnd = random.Random(1)
    pts = [(2 * i + rnd.uniform(-0.1, 0.1), 2 * j + rnd.uniform(-0.1, 0.1), 2 * k + rnd.uniform(-0.1, 0.1))
           for i in range(-6, 7) for j in range(-6, 7) for k in range(-6, 7)]
    centres = [[rnd.uniform(-1, 1) for _ in range(3)] for _ in range(20)]
    rows = []
    for e in (0.25, 0.5, 1.0, 2.0):
        res = [bounds(c, e * R, pts) for c in centres]
        for name, col in (("monotone", 0), ("taylor", 1)):
            v = [r[col] for r in res]
            rows.append((name, e, min(v), sum(v) / len(v), sum(x >= ISO for x in v) / len(v)))
        phis = [r[2] for r in res]
    with open(out, "w") as f:
        f.write("# %s; experiments/bench/interior_bounds.py: lower bounds of phi over boxes of edge e inside a liquid\n" % study_commit())
        f.write("# lattice 2r, jitter 0.1 r, V (2r)^3, cubic spline, H = 4r, iso 0.6; 20 seeded box centres; phi at the centres %.3f..%.3f\n" % (min(phis), max(phis)))
        f.write("bound,edge_r,lower_min,lower_mean,proven_fraction\n")
        for r in rows: f.write("%s,%g,%.3f,%.3f,%.2f\n" % r)

if __name__ == "__main__":
    main()
