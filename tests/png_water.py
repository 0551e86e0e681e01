#!/usr/bin/env python3
"""Water fraction of 8-bit PNG screenshots (tests/view_methods.sh).

usage: png_water.py FILE.png...
Prints one line per file: "FILE W H FRACTION", FRACTION being the share of
pixels that look like water under the shared shading: blue minus red above
20/255 (0.08, the test of tests/view.sh). The viewer's empty scene has none:
the checker floor and the sky are grey (R = G = B) and the simulator's
container outline is orange (R > B). Reads non-interlaced 8-bit grey, RGB or
RGBA PNGs (what the viewer's screenshots are) with the Python standard
library only; any other PNG is an error (exit 2).
"""
import struct
import sys
import zlib

BLUE_OVER_RED = 20


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, hdr = 8, [], None
    while pos + 8 <= len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if hdr is None:
        raise ValueError("no IHDR")
    w, h, depth, ctype, _, _, interlace = hdr
    nch = {0: 1, 2: 3, 6: 4}.get(ctype)
    if depth != 8 or nch is None or interlace:
        raise ValueError("only 8-bit grey/RGB/RGBA non-interlaced PNGs (depth %d, type %d)" % (depth, ctype))
    raw = zlib.decompress(b"".join(idat))
    stride = w * nch
    rows, prev = [], bytearray(stride)
    for y in range(h):
        ft = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - nch] if i >= nch else 0
            b = prev[i]
            if ft == 1:
                line[i] = (line[i] + a) & 255
            elif ft == 2:
                line[i] = (line[i] + b) & 255
            elif ft == 3:
                line[i] = (line[i] + ((a + b) >> 1)) & 255
            elif ft == 4:
                c = prev[i - nch] if i >= nch else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
            elif ft != 0:
                raise ValueError("bad filter type %d" % ft)
        rows.append(line)
        prev = line
    return w, h, nch, rows


def water_fraction(w, h, nch, rows):
    if nch < 3:
        return 0.0
    n = 0
    for line in rows:
        for x in range(0, w * nch, nch):
            if line[x + 2] - line[x] > BLUE_OVER_RED:
                n += 1
    return n / float(w * h)


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    rc = 0
    for path in argv[1:]:
        try:
            w, h, nch, rows = read_png(path)
        except (OSError, ValueError, zlib.error) as e:
            sys.stderr.write("png_water.py: %s: %s\n" % (path, e))
            print("%s 0 0 -1" % path)
            rc = 2
            continue
        print("%s %d %d %.4f" % (path, w, h, water_fraction(w, h, nch, rows)))
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv))
