#!/usr/bin/env python3
"""The front of the DualSPHysics frame (README.md of this folder): the
particles with x >= 0.72 m (the front at the obstacle) of dambreak200k_t0.300.vtk, as a
binary little-endian PLY of float x, y, z in the file's order.

    make_front.py SHARED/dualsphysics/dambreak200k_t0.300.vtk OUT.ply
"""
import struct
import sys

X_MIN = 0.72


def points(path):
    """The POINTS of a legacy binary VTK file (big-endian floats) as a flat tuple."""
    data = open(path, "rb").read()
    i = data.index(b"POINTS")
    j = data.index(b"\n", i)
    n = int(data[i:j].split()[1])
    return struct.unpack(">%df" % (3 * n), data[j + 1:j + 1 + 12 * n])


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: make_front.py FRAME.vtk OUT.ply")
    p = points(sys.argv[1])
    keep = [k for k in range(len(p) // 3) if p[3 * k] >= X_MIN]
    head = ("ply\nformat binary_little_endian 1.0\ncomment DualSPHysics 01_DamBreak t=0.300, x >= %g m "
            "(experiments/data/dualsphysics/README.md)\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n" % (X_MIN, len(keep)))
    with open(sys.argv[2], "wb") as f:
        f.write(head.encode())
        for k in keep:
            f.write(struct.pack("<3f", *p[3 * k:3 * k + 3]))
    print("%s: %d of %d particles" % (sys.argv[2], len(keep), len(p) // 3))


if __name__ == "__main__":
    main()
