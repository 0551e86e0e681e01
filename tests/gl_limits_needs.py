#!/usr/bin/env python3
"""Keeps common/gl/gl_limits.c's needs true to the shaders (docs/DESIGN.md, "GL limits").

Reads the shader sources tests/glsl_validate.sh dumped (every program the binary compiles,
as the driver gets it), takes each program's resources from the Khronos reference
compiler's reflection (glslangValidator -l -q: the active storage blocks, images,
samplers and uniforms of each stage, the work-group size) and its text (vertex attributes
and outputs, fragment outputs), and fails when a program uses more of a limit than the
table (test_gl_limits --table) says fluidsurf needs: a new binding, block or image must
raise the need, so the context check keeps refusing the drivers that cannot run it.

    gl_limits_needs.py DUMPDIR TABLE.tsv
"""
import collections
import glob
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

STAGE_BITS = {1: "vert", 8: "geom", 16: "frag", 32: "comp"}
# GL type enum -> components; matrices count their columns as vec4 slots below
COMPONENTS = {0x1406: 1, 0x8B50: 2, 0x8B51: 3, 0x8B52: 4, 0x1404: 1, 0x8B53: 2, 0x8B54: 3, 0x8B55: 4,
              0x1405: 1, 0x8DC6: 2, 0x8DC7: 3, 0x8DC8: 4, 0x8B56: 1, 0x8B5A: 4, 0x8B5B: 9, 0x8B5C: 16}
COLUMNS = {0x8B5A: 2, 0x8B5B: 3, 0x8B5C: 4}
SAMPLERS = {0x8B5E, 0x8B5F, 0x8DC1, 0x8B60}
IS_IMAGE = range(0x904C, 0x906D)
COUNTER_BLOCK = "fs_counter_block"  # binding FS_GL_COUNTER_BINDING: gl_counters.c checks it when counting starts
ROW = re.compile(r"(\S+): offset (-?\d+), type (\w+), size (\d+), index (-?\d+), binding (-?\d+), stages (\d+)")
OUT = re.compile(r"^\s*(?:(?:flat|smooth|noperspective)\s+)*out\s+(?:(?:flat|smooth|noperspective)\s+)*"
                 r"(float|vec2|vec3|vec4|int|ivec2|ivec3|ivec4|uint|mat3|mat4)\s+([^;]+);", re.M)
WIDTH = {"float": 1, "int": 1, "uint": 1, "vec2": 2, "ivec2": 2, "vec3": 3, "ivec3": 3, "vec4": 4, "ivec4": 4,
         "mat3": 9, "mat4": 16}


def programs(run):
    """The programs of one run: its index lines grouped by their program column ("PID.N",
    common/gl/shader_dump.h), stages in the order they were compiled."""
    progs = collections.OrderedDict()
    for line in open(os.path.join(run, "index.tsv")):
        stage, defines, name, prog = line.rstrip("\n").split("\t")
        progs.setdefault(prog, []).append((stage, defines, os.path.join(run, name)))
    return list(progs.values())


def reflect(files):
    """{limit: use} of one program, from glslang's reflection and the source text."""
    r = subprocess.run(["glslangValidator", "-l", "-q"] + files, capture_output=True, text=True)
    if r.returncode:
        sys.exit("FAIL glslangValidator -l -q %s: %s" % (" ".join(files), r.stdout.strip()[-300:]))
    use = collections.Counter()
    section = ""
    for line in r.stdout.splitlines():
        if line.endswith("reflection:"):
            section = line
            continue
        size = re.match(r"Local size ([XY]): (\d+)", line)
        if size:
            use["GL_MAX_COMPUTE_WORK_GROUP_SIZE[%s]" % size.group(1).lower()] = int(size.group(2))
        m = ROW.match(line)
        if m and section:
            add_resource(use, section, m)
    text = {f.rsplit(".", 1)[1]: open(f).read() for f in files}
    add_text(use, text)
    x, y = use["GL_MAX_COMPUTE_WORK_GROUP_SIZE[x]"], use["GL_MAX_COMPUTE_WORK_GROUP_SIZE[y]"]
    use["GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS"] = x * max(y, 1)
    return use


def add_resource(use, section, m):
    name, typ, size, index, binding, stages = m.group(1), int(m.group(3), 16), int(m.group(4)), int(m.group(5)), \
        int(m.group(6)), int(m.group(7))
    if section.startswith("Uniform reflection") and index == -1:
        use["GL_MAX_UNIFORM_LOCATIONS"] += size  # one per array element, once per program
    for bit, stage in STAGE_BITS.items():
        if not stages & bit:
            continue
        if section.startswith("Uniform block") and typ == 0xFFFFFFFF:  # glslang lists storage blocks here
            key = {"vert": "VERTEX", "frag": "FRAGMENT", "comp": "COMPUTE", "geom": "GEOMETRY"}[stage]
            use["GL_MAX_%s_SHADER_STORAGE_BLOCKS" % key] += 1
            use["GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS"] += 1
            use["GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES"] += 1
            if name != COUNTER_BLOCK:
                use.update_max("GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS", binding + 1)
        elif section.startswith("Uniform reflection") and index == -1:
            uniform(use, stage, typ, size, binding)


def uniform(use, stage, typ, size, binding):
    if typ in IS_IMAGE:
        use.update_max("GL_MAX_IMAGE_UNITS", binding + 1)
        use["GL_MAX_COMBINED_IMAGE_UNIFORMS"] += 1
        use["GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES"] += 1
        if stage == "comp":
            use["GL_MAX_COMPUTE_IMAGE_UNIFORMS"] += 1
    elif typ in SAMPLERS:
        use[{"frag": "GL_MAX_TEXTURE_IMAGE_UNITS", "comp": "GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS"}.get(stage, "")] += 1
    else:  # a default-block uniform, rounded up to whole vec4s (drivers pack no tighter than that)
        key = {"vert": "VERTEX", "geom": "GEOMETRY", "frag": "FRAGMENT", "comp": "COMPUTE"}[stage]
        use["GL_MAX_%s_UNIFORM_COMPONENTS" % key] += 4 * size * COLUMNS.get(typ, 1)


def add_text(use, text):
    """What reflection of a linked program does not list: the interface between stages."""
    frag = text.get("frag", "")
    outs = [int(n) for n in re.findall(r"layout\(location = (\d+)\) out", frag)]
    use["GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES"] += len(set(outs))
    if outs:
        use["GL_MAX_DRAW_BUFFERS"] = use["GL_MAX_COLOR_ATTACHMENTS"] = max(outs) + 1
    attrs = [int(n) for n in re.findall(r"layout\(location = (\d+)\) in", text.get("vert", ""))]
    if attrs:
        use["GL_MAX_VERTEX_ATTRIBS"] = max(attrs) + 1
    if "geom" not in text:  # with a geometry shader the fragment inputs are its outputs, checked apart
        n = sum(WIDTH[t] * len(names.split(",")) for t, names in OUT.findall(text.get("vert", "")))
        use["GL_MAX_VERTEX_OUTPUT_COMPONENTS"] = use["GL_MAX_FRAGMENT_INPUT_COMPONENTS"] = n


def update_max(self, key, value):
    self[key] = max(self[key], value)


collections.Counter.update_max = update_max


def main():
    dump, table = sys.argv[1], sys.argv[2]
    need = {}
    for line in open(table):
        name, value = line.rstrip("\n").split("\t")
        need[name] = int(value)
    jobs = {}  # files -> label, each distinct program once
    for run in sorted(d for d in glob.glob(os.path.join(dump, "*")) if os.path.isdir(d)):
        for prog in programs(run):
            label = "%s: %s" % (os.path.basename(run), " + ".join(s for s, _, _ in prog))
            if prog[0][1]:
                label += " [%s]" % prog[0][1].split(";FS_CNT_WORDS")[0]
            jobs.setdefault(tuple(f for _, _, f in prog), label)
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        uses = list(pool.map(lambda files: reflect(list(files)), jobs))
    worst = {}  # limit -> (use, program)
    for label, use in zip(jobs.values(), uses):
        for limit, value in use.items():
            if limit and value > worst.get(limit, (0, ""))[0]:
                worst[limit] = (value, label)
    nprog = len(jobs)
    fails = 0
    for limit, (value, label) in sorted(worst.items()):
        if limit not in need:
            print("FAIL %s: %d used by %s, but not in common/gl/gl_limits.c's table" % (limit, value, label))
            fails += 1
        elif value > need[limit]:
            print("FAIL %s: %d used by %s, above the need %d in common/gl/gl_limits.c" % (limit, value, label,
                                                                                         need[limit]))
            fails += 1
        else:
            print("ok   %s: at most %d used (%s); need %d" % (limit, value, label, need[limit]))
    for limit in sorted(set(need) - set(worst)):
        print("--   %s: need %d, not derived from the shaders (set by the C code or the parameter ranges: "
              "docs/DESIGN.md, \"GL limits\")" % (limit, need[limit]))
    if nprog == 0:
        print("FAIL no programs under %s" % dump)
        fails += 1
    print("gl_limits_needs: %d programs, %d limits derived, %d over their need" % (nprog, len(worst), fails))
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
