#!/usr/bin/env python3
"""Per-frame measures of a `fluidsurf simulate` sequence, to pick frames by a rule.

usage: sph_frames.py R FRAME.ply...   (binary little-endian PLY as fluidsurf writes it)

Prints CSV, one row per file:
  file, particles,
  gap_x     min x of phase 1 minus max x of phase 0 (m; the two blocks of
            double_dam_break, which start at the tank's two ends; empty with one phase),
  min_dist  the closest phase-0 / phase-1 pair (m), searched within 4 r only
            (empty when no pair is that close),
  mid_top   the highest particle within 0.1 m of the tank's middle in x (m above the
            lowest particle of the frame; the rising collision sheet),
  y_p999    the 99.9th percentile of height above the lowest particle (m; run-up),
  v_mean    mean speed (m/s).
No numpy: the frames are small (tens of thousands of particles).
"""
import math
import struct
import sys

TYPES = {"float": "f", "float32": "f", "double": "d", "int": "i", "int32": "i", "uint": "I",
         "uchar": "B", "uint8": "B", "char": "b", "short": "h", "ushort": "H"}


def read_ply(path):
    """The vertex properties of a binary little-endian PLY as a dict of lists."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        sys.exit(f"sph_frames.py: {path}: not a PLY file")
    header = data[:end].decode("ascii", "replace").splitlines()
    if "format binary_little_endian 1.0" not in header:
        sys.exit(f"sph_frames.py: {path}: only binary_little_endian PLY is read")
    n, props, in_vertex = 0, [], False
    for line in header:
        w = line.split()
        if w[:2] == ["element", "vertex"]:
            n, in_vertex = int(w[2]), True
        elif w and w[0] == "element":
            in_vertex = False
        elif in_vertex and w and w[0] == "property":
            if w[1] not in TYPES:
                sys.exit(f"sph_frames.py: {path}: property type {w[1]} not read")
            props.append((w[2], TYPES[w[1]]))
    fmt = "<" + "".join(t for _, t in props)
    size = struct.calcsize(fmt)
    body = data[end + len(b"end_header\n"):]
    if len(body) < n * size:
        sys.exit(f"sph_frames.py: {path}: {n} vertices announced, file too short")
    cols = {name: [] for name, _ in props}
    names = [name for name, _ in props]
    for rec in struct.iter_unpack(fmt, body[:n * size]):
        for k, v in zip(names, rec):
            cols[k].append(v)
    return cols


def min_pair(a, b, cell):
    """Closest distance between a point of a and one of b, if below cell; else None."""
    grid = {}
    for p in b:
        grid.setdefault(tuple(int(math.floor(c / cell)) for c in p), []).append(p)
    best = None
    for p in a:
        k = [int(math.floor(c / cell)) for c in p]
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for q in grid.get((k[0] + dx, k[1] + dy, k[2] + dz), ()):
                        d = math.dist(p, q)
                        if d < cell and (best is None or d < best):
                            best = d
    return best


def measure(path, r):
    c = read_ply(path)
    for need in ("x", "y", "z"):
        if need not in c:
            sys.exit(f"sph_frames.py: {path}: no property {need}")
    n = len(c["x"])
    if n == 0:
        sys.exit(f"sph_frames.py: {path}: no particles")
    pts = list(zip(c["x"], c["y"], c["z"]))
    phase = c.get("phase", [0] * n)
    a = [p for p, k in zip(pts, phase) if k == 0]
    b = [p for p, k in zip(pts, phase) if k == 1]
    gap = dist = ""
    if a and b:
        gap = "%.4f" % (min(p[0] for p in b) - max(p[0] for p in a))
        d = min_pair(a, b, 4 * r)
        dist = "" if d is None else "%.4f" % d
    y0 = min(c["y"])
    xc = 0.5 * (min(c["x"]) + max(c["x"]))
    mid = [p[1] - y0 for p in pts if abs(p[0] - xc) < 0.1]
    ys = sorted(y - y0 for y in c["y"])
    p999 = ys[min(n - 1, int(0.999 * n))]
    v = 0.0
    if "vx" in c:
        v = sum(math.sqrt(x * x + y * y + z * z) for x, y, z in zip(c["vx"], c["vy"], c["vz"])) / n
    return "%s,%d,%s,%s,%.4f,%.4f,%.4f" % (path, n, gap, dist, max(mid) if mid else 0.0, p999, v)


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: sph_frames.py R FRAME.ply...")
    try:
        r = float(sys.argv[1])
    except ValueError:
        sys.exit(f"sph_frames.py: R '{sys.argv[1]}' is not a number")
    if not r > 0:
        sys.exit(f"sph_frames.py: R '{sys.argv[1]}' must be positive")
    print("file,particles,gap_x,min_dist,mid_top,y_p999,v_mean")
    for path in sys.argv[2:]:
        print(measure(path, r))


if __name__ == "__main__":
    main()
