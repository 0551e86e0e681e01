#!/usr/bin/env python3
"""Checks the measured numbers typed in Markdown prose against the CSVs they come from.

A measured number in prose carries, right after it, a comment that says where it comes from:

    +76%<!--n xiao2017/fig10.csv 100*[scene=dam_break&iso=0.9]frame_ms/[scene=dam_break&iso=0.6]frame_ms-100 %+.0f%%-->

that is `<!--n CSV EXPR FORMAT-->`: CSV relative to the Markdown file's folder; EXPR arithmetic
over lookups `[COND&...]COLUMN` (the one row that meets every COND; `[]COLUMN` when the CSV has
one row), `min[...]COLUMN`, `max[...]COLUMN`, `med[...]COLUMN` (the median) or `sum[...]COLUMN`
over every matching row, or `count[...]COLUMN` (how many rows match); a COND is COL=VALUE (equal
as text), COL<NUMBER or COL>NUMBER; FORMAT a printf format. The text just before the comment must be what FORMAT makes of EXPR,
so a number that goes stale when its CSV is re-measured fails here.

In results/README.md's verdict column, every number that looks measured (a decimal, a
percentage, a ratio such as 5.25x) must carry such a comment, or `<!--paper-->` when it is
the paper's number; a parameter value written after "=" is left alone.

    check_numbers.py [--fix] [FILE.md ...]   (default: results/README.md, results/*/*.md,
                                              methods/*/README.md)
--fix rewrites each annotated number to what its CSV gives now (after a study is re-run), and
lists each one it changed, so the prose around it can be read again: a claim may have flipped.
Exit 0 when every number agrees (or was fixed), 1 naming each that does not, 2 on bad input.
"""
import csv
import glob
import os
import re
import statistics
import sys

NOTE = re.compile(r"<!--n (\S+) (.+?) (%\S+)-->")
LOOKUP = re.compile(r"(min|max|med|sum|count)?\[([^\]]*)\]([A-Za-z_][A-Za-z0-9_.]*)")
COND = re.compile(r"([^=<>]+)([=<>])(.*)$")
MEASURED = re.compile(r"(?<![\w.=/-])[-+]?\d+(?:\.\d+)?(?:%|x(?![\w])|(?<=\.\d)\d*)")
SAFE = re.compile(r"^[-+*/(). 0-9e]*$")


class Bad(Exception):
    pass


def rel(path):
    return os.path.relpath(path, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../.."))


def read_csv(path, cache={}):
    if path not in cache:
        if not os.path.isfile(path):
            raise Bad("%s does not exist" % path)
        with open(path, newline="") as f:
            lines = [l for l in f.read().splitlines() if l and not l.startswith("#")]
        cache[path] = list(csv.DictReader(lines))
    return cache[path]


def matches(row, conds):
    """Whether a row meets every condition: COL=VALUE (as text), COL<NUMBER or COL>NUMBER."""
    for col, op, want in conds:
        have = row.get(col)
        if op == "=":
            if have != want:
                return False
            continue
        try:
            if not (float(have) < float(want) if op == "<" else float(have) > float(want)):
                return False
        except (TypeError, ValueError):
            return False
    return True


def lookup(rows, agg, filt, col, path):
    conds = [COND.match(c) for c in filt.split("&") if c]
    if not all(conds):
        raise Bad("%s: bad filter [%s]" % (path, filt))
    hit = [r for r in rows if matches(r, [c.groups() for c in conds])]
    if rows and col not in rows[0]:
        raise Bad("%s: no column %s" % (path, col))
    if agg == "count":
        return len(hit)
    if not hit:
        raise Bad("%s: no row [%s]" % (path, filt))
    try:
        vals = [float(r[col]) for r in hit]
    except ValueError:
        raise Bad("%s: [%s]%s is not a number" % (path, filt, col))
    if agg in ("min", "max", "sum"):
        return {"min": min, "max": max, "sum": sum}[agg](vals)
    if agg == "med":
        return statistics.median(vals)
    if len(vals) != 1:
        raise Bad("%s: %d rows match [%s]: name one, or use min/max/med/sum/count" % (path, len(vals), filt))
    return vals[0]


def value(folder, path, expr):
    rows = read_csv(os.path.join(folder, path))
    arith = LOOKUP.sub(lambda m: "(%r)" % lookup(rows, m.group(1), m.group(2), m.group(3), path), expr)
    if not SAFE.match(arith):
        raise Bad("%s: cannot evaluate %s" % (path, expr))
    try:
        return eval(arith, {"__builtins__": {}})
    except (ZeroDivisionError, SyntaxError):
        raise Bad("%s: cannot evaluate %s" % (path, expr))


def trailing_number(s):
    """The match of the number that ends s (an exponent included; a sign only after a space or
    an opening bracket, so a range's hyphen as in 0.7-1.2 or 80<!--n ...-->-300 is not), or None."""
    m = re.search(r"\d[\d.,]*(?:[eE][-+]?\d+)?%?x?$", s)
    if not m:
        return None
    start = m.start()
    if start > 0 and s[start - 1] in "-+" and (start == 1 or s[start - 2] in " \t\n([~"):
        start -= 1
    return re.compile(re.escape(s[start:]) + "$").search(s, start)


def fix_notes(md, text):
    """text with each annotated number replaced by its CSV's value; prints each change."""
    folder, out, last = os.path.dirname(os.path.abspath(md)), [], 0
    for m in NOTE.finditer(text):
        try:
            want = m.group(3) % value(folder, m.group(1), m.group(2))
        except Bad:
            continue  # check_notes reports it
        got = trailing_number(text[:m.start()])
        before = text[last:m.start()]
        if got and got.start() >= last and got.group(0) != want:
            line = text.count("\n", 0, m.start()) + 1
            print("%s:%d: %s -> %s" % (rel(md), line, got.group(0), want))
            before = text[last:got.start()] + want
        out.append(before + m.group(0))
        last = m.end()
    return "".join(out) + text[last:]


def check_notes(md, text):
    """Errors for each <!--n--> note whose text before it is not its value."""
    errs, folder = [], os.path.dirname(os.path.abspath(md))
    for m in NOTE.finditer(text):
        line = text.count("\n", 0, m.start()) + 1
        try:
            want = m.group(3) % value(folder, m.group(1), m.group(2))
        except Bad as e:
            errs.append("%s:%d: %s" % (rel(md), line, e))
            continue
        before = text[:m.start()]
        if not before.endswith(want) or re.search(r"[\d.]$", before[:len(before) - len(want)]):
            got = trailing_number(before)
            errs.append("%s:%d: the text says %s, %s gives %s" % (rel(md), line, got.group(0) if got else "nothing", m.group(1), want))
    return errs


def verdicts(text):
    """(item, verdict cell) of each row of results/README.md's index."""
    for line in text.splitlines():
        if line.startswith("| ") and not line.startswith("| item |"):
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            if len(cells) == 5:
                yield cells[0], cells[3]


def check_bare(md, text):
    """Errors for each measured-looking number of the index's verdicts without a note."""
    errs = []
    for item, cell in verdicts(text):
        cell = re.sub(r"\[[^\]]*\]\([^)]*\)|`[^`]*`", " ", cell)  # links and code name files
        cell = re.sub(r"<!--n .*?-->", "<!--n -->", cell)  # a note's own expression is not prose
        for m in MEASURED.finditer(cell):
            rest = cell[m.end():]
            if rest.startswith("<!--n ") or rest.startswith("<!--paper-->"):
                continue
            if re.search(r"=\s*$", cell[:m.start()]):
                continue  # a parameter value
            if re.search(r"\b(?:[Ss]ections?|[Ee]qs?\.)\s*$", cell[:m.start()]):
                continue  # a reference to the paper's text
            errs.append("%s: %s: %s has no <!--n CSV ...--> or <!--paper--> note" % (rel(md), item, m.group(0)))
    return errs


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")
    args = sys.argv[1:]
    fix = "--fix" in args
    args = [a for a in args if a != "--fix"]
    files = args or sorted(
        [os.path.join(root, "results/README.md")] + glob.glob(os.path.join(root, "results/*/*.md")) +
        glob.glob(os.path.join(root, "methods/*/README.md")))
    errs, notes = [], 0
    for md in files:
        if not os.path.isfile(md):
            sys.stderr.write("check_numbers: %s: no such file\n" % md)
            sys.exit(2)
        text = open(md, encoding="utf-8").read()
        if fix:
            fixed = fix_notes(md, text)
            if fixed != text:
                with open(md + ".tmp", "w", encoding="utf-8") as f:
                    f.write(fixed)
                os.replace(md + ".tmp", md)
                text = fixed
        notes += len(NOTE.findall(text))
        errs += check_notes(md, text)
        if os.path.basename(md) == "README.md" and os.path.basename(os.path.dirname(os.path.abspath(md))) == "results":
            errs += check_bare(md, text)
    for e in errs:
        print(e)
    if errs:
        print("check_numbers: %d numbers disagree with their CSVs or name none" % len(errs))
        sys.exit(1)
    print("check_numbers: %d numbers in %d files agree with their CSVs" % (notes, len(files)))


if __name__ == "__main__":
    main()
