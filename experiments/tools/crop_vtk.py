#!/usr/bin/env python3
"""The particles of a DualSPHysics legacy VTK frame (BINARY, big-endian POLYDATA:
POINTS, VERTICES, POINT_DATA with SCALARS Idp and FIELD Vel, Rhop, as PartVTK
writes it) inside a box, written in the same layout with every array kept.

    crop_vtk.py IN.vtk OUT.vtk XMIN,YMIN,ZMIN XMAX,YMAX,ZMAX

Made experiments/data/dualsphysics/'s crop of the shared frame."""
import sys

import numpy as np


def section(b, tag, start):
    """Offset just after the header line that starts with tag, and that line."""
    i = b.index(tag, start)
    j = b.index(b"\n", i) + 1
    return j, b[i:j]


def read(path):
    b = open(path, "rb").read()
    j, line = section(b, b"POINTS", 0)
    n = int(line.split()[1])
    pos = np.frombuffer(b, ">f4", 3 * n, j).reshape(n, 3)
    j, _ = section(b, b"LOOKUP_TABLE", j)
    idp = np.frombuffer(b, ">u4", n, j)
    j, _ = section(b, b"\nVel ", j)
    vel = np.frombuffer(b, ">f4", 3 * n, j).reshape(n, 3)
    j, _ = section(b, b"\nRhop ", j)
    rhop = np.frombuffer(b, ">f4", n, j)
    return pos, idp, vel, rhop


def write(path, pos, idp, vel, rhop):
    m = len(pos)
    with open(path, "wb") as f:
        f.write(b"# vtk DataFile Version 3.0\nvtk output\nBINARY\nDATASET POLYDATA\nPOINTS %d float\n" % m)
        f.write(pos.astype(">f4").tobytes())
        f.write(b"\nVERTICES %d %d\n" % (m, 2 * m))
        f.write(np.stack([np.ones(m), np.arange(m)], 1).astype(">i4").tobytes())
        f.write(b"\nPOINT_DATA %d\nSCALARS Idp unsigned_int\nLOOKUP_TABLE default\n" % m)
        f.write(idp.astype(">u4").tobytes())
        f.write(b"\nFIELD FieldData 2\nVel 3 %d float\n" % m)
        f.write(vel.astype(">f4").tobytes())
        f.write(b"\nRhop 1 %d float\n" % m)
        f.write(rhop.astype(">f4").tobytes())
        f.write(b"\n")


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    lo, hi = (np.array([float(v) for v in a.split(",")]) for a in sys.argv[3:5])
    pos, idp, vel, rhop = read(sys.argv[1])
    keep = np.all((pos >= lo) & (pos <= hi), axis=1)
    write(sys.argv[2], pos[keep], idp[keep], vel[keep], rhop[keep])
    print("%d of %d particles" % (keep.sum(), len(pos)))


if __name__ == "__main__":
    main()
