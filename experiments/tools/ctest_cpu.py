#!/usr/bin/env python3
"""Makes every test of a CMake build directory record its own CPU time, for
experiments/bench/test_times.sh: each add_test of the build's CTestTestfile.cmake
files gets /usr/bin/time in front, which writes DIR/NAME.time ("wall user sys" in
seconds, the test and every child it waited for). ctest's own timing gives only wall
time, which other work on a shared machine inflates; CPU time barely moves with it.

    ctest_cpu.py wrap BUILD DIR    wrap every test (the originals kept as *.orig)
    ctest_cpu.py unwrap BUILD      put the originals back
    ctest_cpu.py read DIR          "NAME,wall_s,cpu_s" for every DIR/NAME.time
"""
import os
import re
import sys

ADD = re.compile(r"^add_test\(\[=\[(?P<name>[^]]+)\]=\] ")


def testfiles(build):
    for root, _, files in os.walk(build):
        if "CTestTestfile.cmake" in files and "CMakeFiles" not in root:
            yield os.path.join(root, "CTestTestfile.cmake")


def wrap(build, out):
    os.makedirs(out, exist_ok=True)
    for f in testfiles(build):
        if os.path.exists(f + ".orig"):
            raise SystemExit("ctest_cpu.py: %s is wrapped already (unwrap it first)" % f)
        text = open(f).read()
        os.rename(f, f + ".orig")

        def timed(m):
            path = os.path.join(out, m.group("name") + ".time")
            return '%s"/usr/bin/time" "-o" "%s" "-f" "%%e %%U %%S" ' % (m.group(0), path)
        open(f, "w").write("\n".join(ADD.sub(timed, l) for l in text.split("\n")))


def unwrap(build):
    for f in testfiles(build):
        if os.path.exists(f + ".orig"):
            os.replace(f + ".orig", f)


def read(out):
    print("test,wall_s,cpu_s")
    for name in sorted(os.listdir(out)):
        if not name.endswith(".time"):
            continue
        # the last line; a failed test's file starts with "Command exited with non-zero status N"
        last = open(os.path.join(out, name)).read().split("\n")
        nums = [l for l in last if re.match(r"^[0-9.]+ [0-9.]+ [0-9.]+$", l)]
        if nums:
            wall, user, sys_ = (float(x) for x in nums[-1].split())
            print("%s,%.2f,%.2f" % (name[:-5], wall, user + sys_))


if __name__ == "__main__":
    a = sys.argv[1:]
    if len(a) == 3 and a[0] == "wrap":
        wrap(a[1], a[2])
    elif len(a) == 2 and a[0] == "unwrap":
        unwrap(a[1])
    elif len(a) == 2 and a[0] == "read":
        read(a[1])
    else:
        sys.exit(__doc__)
