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

Numbers that look measured need such a comment, `<!--paper-->` (the paper's number) or
`<!--set-->` (a setting's value: a default, a limit, a budget): every time (12 ms) in the
prose, and in verdict sentences (results/README.md's verdict column, a paragraph with a bold
verdict) every decimal, percentage, ratio, integer and number written out; what is left
alone (a parameter after "=", a reference, a size, a count of the setup) is in
bare_numbers.py.

    check_numbers.py [--fix] [FILE.md ...]   (default: docs/DESIGN.md, README.md, every .md
                                              under results/, every README.md under methods/)
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

import bare_numbers

NOTE = re.compile(r"<!--n (\S+) (.+?) (%\S+)-->")
LOOKUP = re.compile(r"(min|max|med|sum|count)?\[([^\]]*)\]([A-Za-z_][A-Za-z0-9_.]*)")
COND = re.compile(r"([^=<>]+)([=<>])(.*)$")
SAFE = re.compile(r"^[-+*/(). 0-9e]*$")


class Bad(Exception):
    pass


def rel(path):
    return os.path.relpath(path, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


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


def check_bare(md, text):
    """Errors for each number bare_numbers.py wants a note for and that has none."""
    where = rel(md)
    is_index = os.path.basename(md) == "README.md" and os.path.basename(os.path.dirname(os.path.abspath(md))) == "results"
    return ["%s:%d: %s%s has no <!--n CSV ...-->, <!--paper--> or <!--set--> note" % (where, ln, item + ": " if item else "", x)
            for ln, item, x in bare_numbers.findings(text, is_index)]


def default_files(root):
    """docs/DESIGN.md, README.md and every Markdown file under results/ and README under methods/."""
    return sorted([os.path.join(root, "docs/DESIGN.md"), os.path.join(root, "README.md")] +
                  glob.glob(os.path.join(root, "results/**/*.md"), recursive=True) +
                  glob.glob(os.path.join(root, "methods/**/README.md"), recursive=True))


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    args = sys.argv[1:]
    fix = "--fix" in args
    args = [a for a in args if a != "--fix"]
    files = args or default_files(root)
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
        errs += check_bare(md, text)
    for e in errs:
        print(e)
    if errs:
        print("check_numbers: %d numbers disagree with their CSVs or name none" % len(errs))
        sys.exit(1)
    print("check_numbers: %d numbers in %d files agree with their CSVs" % (notes, len(files)))


if __name__ == "__main__":
    main()
