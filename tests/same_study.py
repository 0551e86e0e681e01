#!/usr/bin/env python3
"""same_study.py A B [--skip NAME]...: are two study folders (compare, merge or
shard outputs) the same file for file, byte for byte, but for times and the
command line report.md records? Text files are compared with those fields
masked (the CSVs' *_ms columns, report.md's command and frame times, a shard
manifest's timings, report.html's embedded copies of them); EXRs by their
header attributes (fluidsurf:runs, fluidsurf:frame_ms and capDate masked) and
their pixel chunks byte for byte; PNGs chunk by chunk. panel.png's captions
hold frame times: compare it byte for byte only when the runs' clocks agree,
else --skip it. --any-commit: what the commit decides is masked too (two builds compared,
experiments/study/same_outputs.sh): the commit and dirty flag, the EXRs' fluidsurf:item (a
hash of their provenance) and the reference cache's file names (its key holds the commit). Prints one line per difference;
exit 1 when there is one.
tests/python/test_fluidsurf.py uses it for Python's compare(out=DIR) against
`fluidsurf compare -o DIR`."""
import json
import re
import struct
import sys
import zlib
from pathlib import Path

TIME = "T"
ANY_COMMIT = False
# "commit=abc; dirty=0" (CSV), "fluidsurf:commit`: abc" (report.md), "commit\tabc" (shard.txt)
COMMIT = re.compile(r"\b(commit|dirty)(`?[=:\t] ?)([0-9a-f]+|unknown)\b")
CACHE_FILE = re.compile(r"\bgbuffer-[0-9a-f]{16}\.exr")


def mask_csv(text):
    out, cols = [], None
    for line in text.splitlines(keepends=True):
        if line.startswith("#"):
            out.append(line)
            continue
        cells = line.rstrip("\n").split(",")
        if cols is None:
            cols = [i for i, c in enumerate(cells) if c.endswith("_ms") or "ms_" in c]
            out.append(line)
            continue
        # a quoted renderer may hold commas: time columns come before it
        for i in cols:
            if i < len(cells):
                cells[i] = TIME
        out.append(",".join(cells) + ("\n" if line.endswith("\n") else ""))
    return "".join(out)


def mask_runs(text):
    """'stage=ms/gpu,...;...' with the numbers masked."""
    return re.sub(r"=([-0-9.eE+naif]+)/([-0-9.eE+naif]+)", "=T/T", text)


def mask_md(text):
    lines = text.splitlines(keepends=True)
    for i, line in enumerate(lines):
        if line.startswith("    fluidsurf"):  # the command line under "Reproduce with:"
            lines[i] = "    <command>\n"
    out, time_col = [], None
    for line in lines:
        if line.startswith("| method | variant |"):
            heads = [c.strip() for c in line.strip().strip("|").split("|")]
            time_col = heads.index("frame (ms)") if "frame (ms)" in heads else None
        elif not line.startswith("|"):
            time_col = None
        elif time_col is not None and not line.startswith("|---"):
            cells = line.rstrip("\n").strip().strip("|").split("|")
            if time_col < len(cells):
                cells[time_col] = " T "
            line = "|" + "|".join(cells) + "|\n"
        out.append(line)
    return "".join(out)


def mask_shard(text):
    out = []
    for line in text.splitlines(keepends=True):
        f = line.rstrip("\n").split("\t")
        if f[0] == "ref" and len(f) == 8:
            f[6] = mask_runs(f[6])
        elif f[0] == "entry" and len(f) == 8:
            f[4], f[5] = TIME, mask_runs(f[5])
        elif f[0] == "prov" and len(f) == 3 and f[1] in ("fluidsurf:frame_ms",):
            f[2] = TIME
        out.append("\t".join(f) + ("\n" if line.endswith("\n") else ""))
    return "".join(out)


def mask_commit(text):
    return CACHE_FILE.sub("gbuffer-C.exr", COMMIT.sub(r"\1\2C", text)) if ANY_COMMIT else text


def mask_attr(name, value):
    if ANY_COMMIT and name in ("fluidsurf:commit", "fluidsurf:dirty", "fluidsurf:item"):
        return "C"
    if name == "fluidsurf:runs":
        return mask_runs(value)
    if name in ("fluidsurf:frame_ms", "capDate"):
        return TIME
    return value


HTML_DATA = re.compile(r'(<script id="fs-data" type="application/json">\n)(.*?)(\n?</script>)', re.S)


def mask_html(text):
    m = HTML_DATA.search(text)
    if not m:
        return text
    data = json.loads(m.group(2))
    for k, v in data.items():
        if isinstance(v, str):
            data[k] = mask_md(v) if k == "report_md" else mask_csv(v)
    return text[: m.start(2)] + json.dumps(data, sort_keys=True) + text[m.end(2):]


def exr_parts(b):
    """(attributes as {name: (type, value)}, offsets relative to the header's end, the chunks)."""
    pos, attrs = 8, {}
    while b[pos] != 0:
        name_end = b.index(0, pos)
        type_end = b.index(0, name_end + 1)
        name, typ = b[pos:name_end].decode(), b[name_end + 1:type_end].decode()
        (size,) = struct.unpack_from("<i", b, type_end + 1)
        val = b[type_end + 5:type_end + 5 + size]
        attrs[name] = (typ, mask_attr(name, val.decode("latin-1")) if typ == "string" else val)
        pos = type_end + 5 + size
    pos += 1
    header_end = pos
    (dw,) = [v for k, (t, v) in attrs.items() if k == "dataWindow"]
    ymin, ymax = struct.unpack_from("<ii", dw, 4)[0], struct.unpack_from("<iiii", dw)[3]
    comp = attrs["compression"][1][0]
    lines = {0: 1, 1: 1, 2: 1, 3: 16, 4: 32, 5: 16, 6: 32, 7: 32, 8: 32, 9: 256}.get(comp, 16)
    nchunks = (ymax - ymin + lines) // lines
    offsets = struct.unpack_from("<%dQ" % nchunks, b, pos)
    table_end = pos + 8 * nchunks
    return attrs, [o - header_end for o in offsets], b[table_end:]


def exr_differs(a, b):
    """None, or which attributes differ, or that the pixels do."""
    names = sorted(n for n in set(a[0]) | set(b[0]) if a[0].get(n) != b[0].get(n))
    if names:
        return "EXR attributes differ: " + ", ".join(names)
    return None if a == b else "EXR pixels differ"


def png_chunks(b):
    pos, out = 8, []
    while pos < len(b):
        (n,) = struct.unpack_from(">I", b, pos)
        typ, data = b[pos + 4:pos + 8], b[pos + 8:pos + 8 + n]
        if typ in (b"tEXt", b"iTXt", b"zTXt"):
            key, _, val = data.partition(b"\0")
            if typ == b"zTXt":
                val = zlib.decompress(val[1:])
            data = key + b"\0" + mask_attr(key.decode("latin-1"), val.decode("latin-1")).encode("latin-1")
        out.append((typ, data))
        pos += 12 + n
    return out


def same(a, b, name):
    x, y = a.read_bytes(), b.read_bytes()
    if x == y:
        return None
    if name.endswith(".exr"):
        return exr_differs(exr_parts(x), exr_parts(y))
    if name.endswith(".png"):
        return None if png_chunks(x) == png_chunks(y) else "PNG differs"
    tx, ty = mask_commit(x.decode("utf-8", "replace")), mask_commit(y.decode("utf-8", "replace"))
    if name.endswith(".csv"):
        tx, ty = mask_csv(tx), mask_csv(ty)
    elif name.endswith(".md"):
        tx, ty = mask_md(tx), mask_md(ty)
    elif name.endswith(".html"):
        tx, ty = mask_html(tx), mask_html(ty)
    elif name == "shard.txt":
        tx, ty = mask_shard(tx), mask_shard(ty)
    if tx == ty:
        return None
    for i, (lx, ly) in enumerate(zip(tx.splitlines(), ty.splitlines())):
        if lx != ly:
            return "line %d: %r != %r" % (i + 1, lx[:160], ly[:160])
    return "lengths differ"


def main(argv):
    global ANY_COMMIT
    skip = set()
    args = []
    it = iter(argv)
    for a in it:
        if a == "--skip":
            skip.add(next(it))
        elif a == "--any-commit":
            ANY_COMMIT = True
        else:
            args.append(a)
    A, B = Path(args[0]), Path(args[1])
    na = {p.relative_to(A).as_posix() for p in A.rglob("*") if p.is_file()} - skip
    nb = {p.relative_to(B).as_posix() for p in B.rglob("*") if p.is_file()} - skip
    bad = 0
    for n in sorted(na ^ nb):
        print("only in %s: %s" % (A if n in na else B, n))
        bad += 1
    for n in sorted(na & nb):
        why = same(A / n, B / n, Path(n).name)
        if why:
            print("%s: %s" % (n, why))
            bad += 1
    print("%d file(s) compared, %d differ" % (len(na & nb), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
