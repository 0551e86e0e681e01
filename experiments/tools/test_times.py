#!/usr/bin/env python3
"""The tables of experiments/bench/test_times.sh, from what scripts/test.sh left:
    TIMES/stage_NAME.csv   a stage's "name,wall_s,cpu_s,budget_s,commit,dirty"
    TIMES/NAME.xml         a ctest stage's JUnit report (ctest's own per-test wall times)
    TIMES/cpu/BUILD/*.time each test's "wall user sys" (experiments/tools/ctest_cpu.py)
    STUDIES                run_all.sh --quick's "study,wall_s,cpu_s"
Writes OUT/test_stages.csv (a row a stage, in the suite's order) and OUT/test_times.csv
(a row a test or study, longest first within its stage). Every stage must have run at
one commit; the CSVs name it.

    test_times.py TIMES STUDIES OUT
"""
import csv
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

ORDER = ["setup", "format", "build", "ctest_quick", "lean_build", "asan_build", "fuzz_build", "ctest",
         "studies", "builds_wait", "lean_ctest", "asan_ctest", "fuzz"]
CTEST_BUILD = {"ctest_quick": "build", "ctest": "build", "lean_ctest": "build-lean", "asan_ctest": "build-asan"}


def read_stages(times):
    stages = {}
    for name in ORDER:
        path = os.path.join(times, "stage_%s.csv" % name)
        if os.path.exists(path):
            row = open(path).read().strip().split(",")
            stages[name] = dict(zip(["stage", "wall_s", "cpu_s", "budget_s", "commit", "dirty"], row))
    if not stages:
        sys.exit("test_times.py: no stage_*.csv in %s (run scripts/test.sh first)" % times)
    made = {(s["commit"], s["dirty"]) for s in stages.values()}
    if len(made) != 1:
        sys.exit("test_times.py: the stages ran at different commits: %s" %
                 ", ".join("%s %s@%s dirty=%s" % (n, s["stage"], s["commit"], s["dirty"])
                           for n, s in stages.items()))
    return stages, made.pop()


def cpu_times(times, build):
    d = os.path.join(times, "cpu", build)
    if not os.path.isdir(d):
        return {}
    out = subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "ctest_cpu.py"), "read", d],
                         check=True, capture_output=True, text=True).stdout
    return {r["test"]: r["cpu_s"] for r in csv.DictReader(out.splitlines())}


def ctest_rows(times, stage):
    junit = os.path.join(times, stage + ".xml")
    if not os.path.exists(junit):
        return []
    cpu = cpu_times(times, CTEST_BUILD[stage])
    rows = []
    for case in ET.parse(junit).getroot().iter("testcase"):
        status = "skipped" if case.find("skipped") is not None else \
            "failed" if case.find("failure") is not None else "passed"
        rows.append([stage, "test", case.get("name"), status, "%.2f" % float(case.get("time")),
                     cpu.get(case.get("name"), "")])
    return rows


def study_rows(path):
    return [["studies", "study", r["study"], "passed", r["wall_s"], r["cpu_s"]]
            for r in csv.DictReader(open(path))] if os.path.exists(path) else []


def main(times, studies, out):
    stages, (commit, dirty) = read_stages(times)
    prov = ("# commit=%s; dirty=%s; machine=%d cores; renderer=llvmpipe (OSMesa, EGL in the lean build); "
            "wall_s as ctest and the shell saw it, cpu_s user+system with children" % (commit, dirty, os.cpu_count()))
    with open(os.path.join(out, "test_stages.csv"), "w") as f:
        f.write(prov + "\nstage,wall_s,cpu_s,budget_s\n")
        for s in stages.values():
            f.write("%s,%s,%s,%s\n" % (s["stage"], s["wall_s"], s["cpu_s"], s["budget_s"]))
    rows = []
    for stage in stages:
        part = ctest_rows(times, stage) if stage in CTEST_BUILD else \
            study_rows(studies) if stage == "studies" else []
        rows += sorted(part, key=lambda r: -float(r[4]))
    with open(os.path.join(out, "test_times.csv"), "w") as f:
        f.write(prov + "\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["stage", "kind", "name", "status", "wall_s", "cpu_s"])
        w.writerows(rows)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
