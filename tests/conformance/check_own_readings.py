#!/usr/bin/python3
"""Runs the wrong readings of own_readings_backend.py as `recode conform --exec` back ends and
holds the report's stages to the stages the readings break.

For each reading: `recode conform --exec "python3 own_readings_backend.py READING" --explain 1`
must fail some vector. Prints one line per reading: its failing vectors, the share of them
diagnosed at the stage the reading breaks (the vector's stage under "Failures explained": its
first bad pixel's, read from the pixel's history, with the kit's wrong readings at hand as the
report has them), the other stages given, and the kit's reading the run is named after, if any.
With --goal, the share must also be at least MIN_SHARE (docs/conformance.md says which readings
reach it).

Usage: check_own_readings.py [--goal] RECODE [READING ...]     exit 0: passed; 1: failed
"""
import collections
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
from own_readings_backend import READINGS  # noqa: E402

MIN_SHARE = 0.95


def run(recode, reading):
    """The stage of each failing vector and the readings the run is named after."""
    cmd = [recode, "conform", "--explain", "1", "--exec",
           "%s %s %s" % (sys.executable, os.path.join(HERE, "own_readings_backend.py"), reading)]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if r.returncode not in (0, 2):
        raise RuntimeError("%s exited with %d: %s" % (reading, r.returncode, r.stderr[-2000:]))
    explained = r.stdout.split("\nFailures explained:\n", 1)[-1]
    stages = {}
    vector = None
    for line in explained.splitlines():
        m = re.match(r"  FAIL  (\S+): ", line)
        if m:
            vector = m.group(1)
            continue
        m = re.match(r"        stage: ([a-z ]+), ", line)
        if m and vector and vector not in stages:
            stages[vector] = m.group(1)
    named = re.findall(r"\nbehaves like: [^\n]*\((\w+)\)", r.stdout)
    return stages, named


def main():
    args = sys.argv[1:]
    goal = "--goal" in args
    args = [a for a in args if a != "--goal"]
    if not args:
        print(__doc__)
        return 2
    if os.environ.get("RECODE_LONG_TESTS_GATE") and os.environ.get("RECODE_LONG_TESTS") != "1":
        print("SKIP: a long test: set RECODE_LONG_TESTS=1 to run it")
        return 77
    recode = args[0]
    readings = args[1:] or list(READINGS)
    problems = []
    start = time.time()
    for reading in readings:
        expected = READINGS[reading]
        by_vector, named = run(recode, reading)
        failing = list(by_vector)
        stages = collections.Counter(by_vector.values())
        share = stages[expected] / len(failing) if failing else 0.0
        others = ", ".join("%s %d" % (s, n) for s, n in stages.most_common() if s != expected)
        print("%-30s %-12s %3d failing, %5.1f %% at its stage%s%s"
              % (reading, expected, len(failing), 100 * share,
                 " (others: %s)" % others if others else "",
                 "; named %s" % ", ".join(named) if named else ""))
        if not failing:
            problems.append("%s passes every vector" % reading)
        elif goal and share < MIN_SHARE:
            problems.append("%s: %.1f %% of its %d failing vectors diagnosed at %s, below %.0f %%"
                            % (reading, 100 * share, len(failing), expected, 100 * MIN_SHARE))
    for p in problems:
        print("FAIL: " + p)
    print("%d readings in %.1f s" % (len(readings), time.time() - start))
    if problems:
        return 1
    print("own readings OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
