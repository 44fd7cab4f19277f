#!/usr/bin/env python3
"""recode run --mode: the conservative mode reports every pair the reference mode reports (its
blocks contain the reference's, so it never misses one), every mode lists the same pair tests
(the broad phase does not depend on the mode), the header names a mode other than the
reference, and the reference mode's output has no "mode" key (its bytes are as before). The
skip-apart mode reports the reference's pairs and contact regions exactly, with pairs skipped.

    check_run_modes.py RECODE SCENE FRAMES
"""
import json
import subprocess
import sys


def run(recode, scene, frames, mode):
    out = subprocess.run([recode, "run", scene, "--frames", frames, "--json", "--no-timing",
                          "--mode", mode], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def pairs(report):
    return {(f["frame"], p["object_a"], p["leaf_a"], p["object_b"], p["leaf_b"])
            for f in report["frames"] for p in f["pairs"]}


def main():
    recode, scene, frames = sys.argv[1:4]
    reports = {m: run(recode, scene, frames, m)
               for m in ("reference", "adaptive", "conservative", "skip-apart")}
    failures = []
    if "mode" in reports["reference"]:
        failures.append('the reference mode\'s header has a "mode" key')
    for mode in ("adaptive", "conservative", "skip-apart"):
        if reports[mode].get("mode") != mode:
            failures.append(f'--mode {mode}: the header says "mode": {reports[mode].get("mode")!r}')
        tests = [f["pair_tests"] for f in reports[mode]["frames"]]
        if tests != [f["pair_tests"] for f in reports["reference"]["frames"]]:
            failures.append(f"--mode {mode}: the pair tests per frame differ from the reference's")
    reference, conservative = pairs(reports["reference"]), pairs(reports["conservative"])
    if not reference:
        failures.append("the reference mode found no contact: nothing was compared")
    missing = sorted(reference - conservative)
    if missing:
        failures.append(f"the conservative mode misses {len(missing)} of the reference's contacts, "
                        f"first {missing[0]}")
    # random-cones has contacts the reference misses between pixel centres (recode bench counts
    # 13 in its quick level) and pairs within a pixel of touching: both other modes must see
    # more, or --mode did not reach the pair tests.
    for mode in ("adaptive", "conservative"):
        if not pairs(reports[mode]) - reference:
            failures.append(f"--mode {mode} found no contact the reference mode did not")
    if "pair_tests_skipped" in reports["reference"]["stats"]:
        failures.append('the reference mode\'s stats have a "pair_tests_skipped" key')
    skip = reports["skip-apart"]
    if [f["pairs"] for f in skip["frames"]] != [f["pairs"] for f in reports["reference"]["frames"]]:
        failures.append("--mode skip-apart: the pairs or contact regions differ from the reference's")
    skipped = skip["stats"].get("pair_tests_skipped", 0)
    apart = skip["stats"]["pair_tests"] - skip["stats"]["contacts"]
    if not 0 < skipped <= apart:
        failures.append(f"--mode skip-apart: {skipped} pair tests skipped, of {apart} apart")
    for f in failures:
        print("FAIL:", f)
    print(f"{scene}: reference {len(reference)} contacts, adaptive "
          f"{len(pairs(reports['adaptive']))}, conservative {len(conservative)}, skip-apart "
          f"{len(pairs(skip))} ({skipped} pair tests skipped)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
