#!/usr/bin/env python3
"""Fails when a function of the product code (cli/, common/, methods/, api/) is 60
lines or longer, counted from the first line of its definition to its closing brace
(docs/DESIGN.md, "Code style"). The code is formatted as .clang-format says, so a
function's body opens with "{" alone at the start of a line and closes with "}" at
the start of a line, and its signature begins at the last line above that starts
in the first column. ALLOWED lists the few that read better whole, each with why.

usage: scripts/check_function_length.py [FILE...]   (default: every tracked C and C++
source under cli/, common/, methods/, api/); run by scripts/check_format.sh."""
import re
import subprocess
import sys

LIMIT = 60
AREAS = ("cli/", "common/", "methods/", "api/")
# "path:function": why it stays whole
ALLOWED = {}


def functions(path):
    """(first line, lines, name) of each function definition in path."""
    lines = open(path, encoding="utf-8", errors="replace").read().split("\n")
    for i, line in enumerate(lines):
        if not line.startswith("{"):
            continue
        s = i - 1
        while s > 0 and lines[s][:1] in (" ", "\t"):
            s -= 1
        if re.match(r"(namespace|class|struct|union|enum|extern)\b", lines[s]):
            continue
        e = i + 1
        while e < len(lines) and not lines[e].startswith("}"):
            e += 1
        name = re.search(r"(\w+)\s*\(", " ".join(lines[s:i]))
        yield s + 1, e - s + 1, name.group(1) if name else "?"


def sources():
    out = subprocess.run(["git", "ls-files", *AREAS], capture_output=True, text=True, check=True).stdout
    return [f for f in out.split() if re.search(r"\.(c|h|cpp)$", f)]


def main(argv):
    files = argv or sources()
    long, seen = [], set()
    for f in files:
        for first, n, name in functions(f):
            key = "%s:%s" % (f, name)
            if n < LIMIT:
                continue
            if key in ALLOWED:
                seen.add(key)
                continue
            long.append("%s:%d: %s is %d lines (under %d: split it where its parts have names)" % (f, first, name, n,
                                                                                                   LIMIT))
    stale = [k for k in ALLOWED if k not in seen and not argv]
    for line in long:
        print("check_function_length: " + line)
    for k in stale:
        print("check_function_length: %s: allowed but no longer %d lines or more: take it off ALLOWED" % (k, LIMIT))
    if long or stale:
        return 1
    print("check_function_length: every function of %s is under %d lines (%d allowed)" % (", ".join(AREAS), LIMIT,
                                                                                            len(ALLOWED)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
