#!/usr/bin/env python3
"""The peers study's region metrics of one render against the reference (peers.sh).

usage: peers_regions.py BIN METHOD.exr REFERENCE.exr R

Prints one CSV fragment: mask_iou,depth_bias_r,depth_p95_r,normal_mean_deg,
interior_normal_mean_deg (fluidsurf diff --json, the whole image), then
thin_px,thin_kept,flat_px,flat_normal_deg over two regions of the reference:
- thin: covered pixels whose reference thickness (the path inside the liquid) is
  under 4 r, a sheet or a drop thinner than two particle diameters; thin_kept is
  the share of them the method covers too.
- flat: covered pixels at least 4 r thick whose 8 neighbours are covered and whose
  reference normal differs from its 4 neighbours' by under 3 degrees (calm water
  seen face on or obliquely); flat_normal_deg is the mean angle between the
  method's and the reference's normal there, over the pixels both cover.
Pixels are read with oiiotool --dumpdata (no numpy needed).
"""
import json
import math
import re
import subprocess
import sys

CHANNELS = ("coverage", "thickness", "normal.X", "normal.Y", "normal.Z")


def read(path):
    """width, height and {channel: [values row by row]} of an EXR fluidsurf wrote."""
    head = subprocess.run(["iinfo", "-v", path], check=True, capture_output=True, text=True).stdout
    m = re.search(r":\s*(\d+) x\s*(\d+)", head)
    w, h = int(m.group(1)), int(m.group(2))
    names = [c.strip() for c in re.search(r"channel list: (.*)", head).group(1).split(",")]
    idx = {c: names.index(c) for c in CHANNELS}
    data = {c: [0.0] * (w * h) for c in CHANNELS}
    dump = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    for line in dump.splitlines():
        m = re.match(r"\s*Pixel \((\d+), (\d+)\): (.*)", line)
        if not m:
            continue
        x, y, vals = int(m.group(1)), int(m.group(2)), m.group(3).split()
        for c, i in idx.items():
            data[c][y * w + x] = float(vals[i])
    return w, h, data


def angle(a, b):
    d = sum(p * q for p, q in zip(a, b))
    return math.degrees(math.acos(max(-1.0, min(1.0, d))))


def normal(img, i):
    return (img["normal.X"][i], img["normal.Y"][i], img["normal.Z"][i])


def regions(m, ref, w, h, r):
    thin = kept = flat = 0
    err = 0.0
    both = 0
    for y in range(1, h - 1):
        for x in range(1, w - 1):
            i = y * w + x
            if ref["coverage"][i] <= 0:
                continue
            t = ref["thickness"][i]
            if t < 4 * r:
                thin += 1
                kept += m["coverage"][i] > 0
                continue
            nb8 = [i + dx + dy * w for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dx or dy]
            if any(ref["coverage"][j] <= 0 for j in nb8):
                continue
            n = normal(ref, i)
            if any(angle(n, normal(ref, j)) >= 3 for j in (i - 1, i + 1, i - w, i + w)):
                continue
            flat += 1
            if m["coverage"][i] > 0:
                both += 1
                err += angle(n, normal(m, i))
    return thin, (kept / thin if thin else float("nan")), flat, (err / both if both else float("nan"))


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__.strip().splitlines()[2])
    binary, mexr, rexr, r = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    d = json.loads(subprocess.run([binary, "diff", mexr, rexr, "--json"], check=True, capture_output=True,
                                  text=True).stdout)
    w, h, m = read(mexr)
    w2, h2, ref = read(rexr)
    if (w, h) != (w2, h2):
        sys.exit(f"peers_regions.py: {mexr} is {w}x{h}, {rexr} {w2}x{h2}")
    thin, kept, flat, nerr = regions(m, ref, w, h, r)
    keys = ("mask_iou", "depth_bias_r", "depth_p95_r", "normal_mean_deg", "interior_normal_mean_deg")
    vals = [d.get(k) for k in keys] + [thin, kept, flat, nerr]
    print(",".join("nan" if v is None else (f"{v:.6g}" if isinstance(v, float) else str(v)) for v in vals))


if __name__ == "__main__":
    main()
