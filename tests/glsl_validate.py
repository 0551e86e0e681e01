#!/usr/bin/env python3
"""Checks the shader sources tests/glsl_validate.sh dumped, one folder per run (compare,
counters, simulate, view), each with index.tsv (stage file, ";"-joined defines, dump name, program):

1. glslangValidator (the Khronos reference compiler) accepts every dumped source as
   GLSL 4.50 core with OpenGL semantics; the layered splat's sources also at every
   INVOCATIONS the binary can choose (1 .. INVOCATIONS_MAX of common/gl/layered_splat.c);
   the compute splatter's sources also with SPLAT_INT64 defined, the variant only a GL
   with 64-bit atomics compiles (llvmpipe has none: common/gl/gl_splat.h).
2. Coverage: every stage file under shaders/ was compiled; every literal defines string
   passed to fs_program_build in the C sources was compiled; every program of the plain
   compare was compiled again with the counter defines in the --counters run.

    glsl_validate.py SRC DUMPDIR
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

STAGE_EXT = (".vert.glsl", ".geom.glsl", ".frag.glsl", ".comp.glsl")
# fs_program_build(STAGES, "LITERAL" ["LITERAL" ...]) in C: adjacent literals concatenate
CALL = re.compile(r'fs_program_build\(\s*[\w\[\]]+\s*,\s*((?:"(?:[^"\\]|\\.)*"\s*)+)\)')


def index(folder):
    """[(stage, defines, dump file)] of one run's folder."""
    path = os.path.join(folder, "index.tsv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [tuple(line.rstrip("\n").split("\t")) for line in f if line.strip()]


def validate(path):
    """glslangValidator's complaint about one source, or None."""
    r = subprocess.run(["glslangValidator", path], capture_output=True, text=True)
    if r.returncode == 0:
        return None
    lines = [l for l in (r.stdout + r.stderr).splitlines() if l.strip() and l.strip() != path]
    return "; ".join(lines[:4])


def invocations_max(src):
    text = open(os.path.join(src, "common/gl/layered_splat.c")).read()
    return int(re.search(r"#define INVOCATIONS_MAX (\d+)", text).group(1))


def invocation_variants(path, nmax, tmp):
    """The source at path with INVOCATIONS set to 1 .. nmax: (value, temporary file)."""
    text = open(path).read()
    ext = os.path.splitext(path)[1]
    os.makedirs(tmp, exist_ok=True)
    for k in range(1, nmax + 1):
        out = os.path.join(tmp, "inv%d%s" % (k, ext))
        with open(out, "w") as f:
            var, n = re.subn(r"(?m)^#define INVOCATIONS \d+$", "#define INVOCATIONS %d" % k, text)
            if n != 1:
                sys.exit("FAIL %s: %d '#define INVOCATIONS' lines, not 1" % (path, n))
            f.write(var)
        yield k, out


def int64_variant(path, tmp):
    """The source at path with SPLAT_INT64 defined after its #version line (a temporary file)."""
    lines = open(path).read().split("\n")
    os.makedirs(tmp, exist_ok=True)
    out = os.path.join(tmp, "int64" + os.path.splitext(path)[1])
    with open(out, "w") as f:
        f.write("\n".join(lines[:1] + ["#define SPLAT_INT64 1"] + lines[1:]))
    return out


def literal_defines(src):
    """Every literal defines string given to fs_program_build in the C sources, ';'-joined."""
    found = set()
    for path in glob.glob(os.path.join(src, "**", "*.c"), recursive=True):
        rel = os.path.relpath(path, src)
        if rel.startswith(("build", "tests/", "out/")):
            continue
        for m in CALL.finditer(open(path).read()):
            text = "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', m.group(1)))
            found.add((rel, text.replace("\\n", ";")))
    return found


def main():
    src, dump = sys.argv[1], sys.argv[2]
    if not shutil.which("glslangValidator"):
        sys.exit("FAIL glslangValidator not found (Debian glslang-tools; scripts/setup.sh installs it)")
    runs = {os.path.basename(d): index(d) for d in sorted(glob.glob(os.path.join(dump, "*"))) if os.path.isdir(d)}
    jobs = []  # (label, source file): each distinct source once (its name holds its hash)
    nmax = invocations_max(src)
    tmp = tempfile.mkdtemp()
    done = set()
    for run, entries in runs.items():
        for name in sorted({e[2] for e in entries} - done):
            done.add(name)
            path = os.path.join(dump, run, name)
            jobs.append(("%s/%s" % (run, name), path))
            if "#define INVOCATIONS " in open(path).read():
                jobs += [("%s/%s with INVOCATIONS %d" % (run, name, k), var)
                         for k, var in invocation_variants(path, nmax, os.path.join(tmp, run + name))]
            text = open(path).read()
            if "#ifdef SPLAT_INT64" in text and "#define SPLAT_INT64" not in text:
                jobs.append(("%s/%s with SPLAT_INT64" % (run, name), int64_variant(path, os.path.join(tmp, run + name))))
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        errs = list(pool.map(lambda j: validate(j[1]), jobs))
    shutil.rmtree(tmp)
    checked = len(jobs)
    fails = ["%s: %s" % (label, e) for (label, _), e in zip(jobs, errs) if e]
    fails += coverage(src, runs)
    for f in fails:
        print("FAIL " + f)
    programs = {(e[0], e[1]) for entries in runs.values() for e in entries}
    print("glsl_validate.py: %d sources (%d stage variants, %d runs) through glslangValidator, %d failures" % (
        checked, len(programs), len(runs), len(fails)))
    sys.exit(1 if fails else 0)


def coverage(src, runs):
    fails = []
    seen = {(e[0], e[1]) for entries in runs.values() for e in entries}
    stages = {s for s, _ in seen}
    for path in sorted(glob.glob(os.path.join(src, "shaders", "**", "*.glsl"), recursive=True)):
        rel = os.path.relpath(path, os.path.join(src, "shaders"))
        if rel.endswith(STAGE_EXT) and not rel.startswith("tests/") and rel not in stages:
            fails.append("shaders/%s was never compiled by the runs" % rel)
    defines = {d for _, d in seen}
    for where, lit in sorted(literal_defines(src)):
        if lit not in defines:
            fails.append("%s: fs_program_build with defines '%s' was never compiled by the runs" % (where, lit))
    counted = {(s, d) for s, d in (e[:2] for e in runs.get("counters", [])) if "FS_COUNTERS 1" in d}
    for s, d in sorted({e[:2] for e in runs.get("compare", [])}):
        if not any(cs == s and cd.startswith(d + ";" if d else "FS_COUNTERS 1") for cs, cd in counted):
            fails.append("%s with defines '%s' has no counting variant in the --counters run" % (s, d))
    if not runs.get("compare"):
        fails.append("the compare run dumped nothing (FS_SHADER_DUMP ignored?)")
    return fails


if __name__ == "__main__":
    main()
