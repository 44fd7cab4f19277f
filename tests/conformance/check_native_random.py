#!/usr/bin/python3
"""Runs random streams of one of the kit's families on a native pipeline of this build and holds
the report to no departure the graphics APIs forbid.

`recode conform --device DEVICE --random COUNT --family FAMILY --seed SEED --keep-going` runs
every stream (a native pipeline fails most of them: its arithmetic is not the contract's); the
summary's "departures the graphics APIs forbid: N vectors" must say 0. The limits family draws
triangles whose vertices lie 32768 pixels out, which a pipeline may clip in single precision.

Usage: check_native_random.py RECODE DEVICE COUNT [SEED] [FAMILY]
With RECODE_LONG_TESTS_GATE set (ctest's long tests), it runs only when RECODE_LONG_TESTS=1.
Exit status 0: passed; 1: failed; 77: skipped (the device is not in this build or has no driver).
"""
import os
import re
import subprocess
import sys
import time

# A device this build or this machine lacks: recode's error names one of these.
MISSING = ("device is not in this build", "no Vulkan driver found", "no physical device",
           "OSMesa: ", "EGL: ")


def main():
    if len(sys.argv) not in (4, 5, 6):
        print(__doc__)
        return 2
    recode, device, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
    if os.environ.get("RECODE_LONG_TESTS_GATE") and os.environ.get("RECODE_LONG_TESTS") != "1":
        print("SKIP: a long test: set RECODE_LONG_TESTS=1 to run it")
        return 77
    seed = sys.argv[4] if len(sys.argv) > 4 else "1"
    family = sys.argv[5] if len(sys.argv) > 5 else "limits"
    cmd = [recode, "conform", "--device", device, "--random", str(count), "--family", family,
           "--seed", seed, "--keep-going", "--explain", "1"]
    start = time.time()
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=3600)
    seconds = time.time() - start
    if r.returncode == 1:
        for what in MISSING:
            if what in r.stderr:
                print("SKIP: %s: %s" % (device, r.stderr.strip().splitlines()[-1]))
                return 77
    if r.returncode not in (0, 2):
        print("FAIL: %s exited with %d: %s" % (" ".join(cmd), r.returncode,
                                              (r.stderr + r.stdout)[-3000:]))
        return 1
    summary = re.search(r"\n(\d+) vectors: (\d+) passed, (\d+) failed", r.stdout)
    if not summary or int(summary.group(1)) != count:
        print("FAIL: no summary of %d vectors: %s" % (count, r.stdout[-2000:]))
        return 1
    forbid = re.search(r"\ndepartures the graphics APIs forbid: (\d+) vectors?\n", r.stdout)
    forbidden = int(forbid.group(1)) if forbid else 0
    if forbidden:
        lines = [l for l in r.stdout.splitlines() if "forbidden by the APIs" in l][:5]
        print("FAIL: %s: %d of %d random %s streams (seed %s) have pixels the graphics APIs "
              "forbid:\n%s" % (device, forbidden, count, family, seed, "\n".join(lines)))
        return 1
    print("native random OK: %s: %d random %s streams of seed %s in %.1f s: %s passed, %s "
          "failed, none with a departure the graphics APIs forbid"
          % (device, count, family, seed, seconds, summary.group(2), summary.group(3)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
