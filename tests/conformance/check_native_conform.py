#!/usr/bin/python3
"""Checks `recode conform`'s verdict against the graphics APIs on a native pipeline of this build
(--device gl: fixed-function OpenGL; --device vulkan-native: Vulkan's own rasterizer).

A native pipeline fails the kit (docs/conformance.md, "Native pipelines"); what is held here is
what the report says of its failures:

1. `recode conform --device DEVICE --json` completes (exit 2: vectors failed) and answers every
   vector.
2. Nothing is called forbidden without its clause: every explained pixel whose `api.allowed` is
   false carries a non-empty `clause`, and where every bad pixel of a vector is explained, as many
   are not allowed as the vector's `api.forbidden_pixels`. The text report, run once on the
   vectors with forbidden pixels, prints "APIs: forbidden by the APIs: <that clause>" under each
   such pixel, their count in the vector's "graphics APIs:" line and the vectors' count in
   "departures the graphics APIs forbid:".
3. No vector has pixels the APIs forbid but those of EXPECTED below (a driver's known bugs); a new
   one fails the test, with its first forbidden pixel and clause.
4. The fingerprint's tie rule is the pipeline's: `taken` is EXPECTED's reading.

Usage: check_native_conform.py RECODE DEVICE WORKDIR
Exit status 0: passed; 1: failed; 77: skipped (the device is not in this build, or it has no
driver or GPU here).
"""

import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
GOLDEN = os.path.join(ROOT, "data", "golden")

# Per device: the vectors allowed to hold pixels the APIs forbid (with why), and the tie rule the
# fingerprint must take. Measured on Mesa's llvmpipe and lavapipe (Debian 12).
EXPECTED = {
    "gl": {
        # kit/depth_arithmetic_33.json's 65536-pixel triangle, whose depth llvmpipe gets about
        # 5% off, is within the clipping freedom.
        "forbidden": {},
        "tie rule": "contract",
    },
    "vulkan-native": {
        "forbidden": {},
        "tie rule": "top_left_fill",
    },
}

# A device this build or this machine lacks: recode's error names one of these.
MISSING = ("device is not in this build", "no Vulkan driver found", "no physical device",
           "OSMesa: ", "EGL: ")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def backend_args(device):
    return ["--device", device]


def conform(recode, device, extra):
    cmd = [recode, "conform"] + backend_args(device) + extra
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if r.returncode == 1:
        for what in MISSING:
            if what in r.stderr:
                print("SKIP: %s: %s" % (device, r.stderr.strip().splitlines()[-1]))
                sys.exit(77)
    if r.returncode not in (0, 2):
        fail("%s exited with %d: %s" % (" ".join(cmd), r.returncode,
                                       (r.stderr + r.stdout)[-3000:]))
    return r.stdout


def check_json(report, expected):
    """Returns the problems, the vectors with forbidden pixels ({file: [(x, y, clause)]}) and
    per such vector its count of forbidden pixels and of explained ones."""
    problems = []
    forbidden = {}
    counts = {}
    for v in report["results"]:
        name = v["file"]
        api = v.get("api") or {}
        n = api.get("forbidden_pixels", 0)
        explained = v.get("explained", [])
        denied = []
        for e in explained:
            verdict = e.get("api")
            if verdict is None:
                problems.append("%s: pixel (%d, %d) is explained without an APIs' verdict"
                                % (name, e["x"], e["y"]))
                continue
            if verdict.get("allowed") is False:
                clause = verdict.get("clause")
                if not isinstance(clause, str) or not clause.strip():
                    problems.append("%s: pixel (%d, %d) is forbidden by the APIs without a "
                                    "clause: %s" % (name, e["x"], e["y"], json.dumps(verdict)))
                else:
                    denied.append((e["x"], e["y"], clause))
        every = n + api.get("freedom_pixels", 0) == len(explained)
        if (every and len(denied) != n) or len(denied) > n:
            problems.append("%s: %d explained pixels are not allowed, but api.forbidden_pixels "
                            "is %d" % (name, len(denied), n))
        if n:
            counts[name] = (n, len(explained))
            forbidden[name] = denied
            if name not in expected["forbidden"]:
                first = ("; first: pixel (%d, %d): %s" % denied[0]) if denied else ""
                problems.append("%s: %d pixels the graphics APIs forbid, and the vector is not "
                                "among the expected ones of this device (%s)%s"
                                % (name, n, ", ".join(sorted(expected["forbidden"])) or "none",
                                   first))
    return problems, forbidden, counts


def check_text(recode, device, work, forbidden, counts):
    """Runs the text report on the vectors with forbidden pixels: each such pixel's "APIs:"
    line gives its clause."""
    golden = os.path.join(work, "golden")
    shutil.rmtree(golden, ignore_errors=True)
    for name in forbidden:
        os.makedirs(os.path.dirname(os.path.join(golden, name)), exist_ok=True)
        shutil.copyfile(os.path.join(GOLDEN, name), os.path.join(golden, name))
    explain = max(e for _, e in counts.values())
    text = conform(recode, device, ["--golden", golden, "--explain", str(explain)])
    with open(os.path.join(work, "report.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    problems = []
    shown = {}          # (vector, x, y) -> the APIs line
    vector = pixel = None
    summary = {}
    for line in text.splitlines():
        m = re.match(r"  FAIL  (\S+): ", line)
        if m:
            vector, pixel = m.group(1), None
            continue
        m = re.match(r"\s+pixel \((\d+), (\d+)\): (depth|stencil) expected", line)
        if m:
            pixel = (int(m.group(1)), int(m.group(2)))
            continue
        m = re.match(r"\s+graphics APIs: (\d+) of \d+ bad pixels are departures the APIs forbid",
                     line)
        if m and vector:
            summary[vector] = int(m.group(1))
            continue
        s = line.strip()
        if s.startswith("APIs: "):
            if vector and pixel:
                shown[(vector, pixel[0], pixel[1])] = s
            if s.startswith("APIs: forbidden by the APIs:"):
                clause = s[len("APIs: forbidden by the APIs:"):].split(";")[0].strip()
                if not clause:
                    problems.append("text: %s pixel %s is forbidden by the APIs without a "
                                    "clause: %s" % (vector, pixel, s))
    for name, denied in forbidden.items():
        if summary.get(name) != counts[name][0]:
            problems.append("text: %s: the \"graphics APIs:\" line counts %s forbidden pixels, "
                            "the JSON %d" % (name, summary.get(name), counts[name][0]))
        for x, y, clause in denied:
            s = shown.get((name, x, y))
            if s is None:
                problems.append("text: %s: pixel (%d, %d), forbidden in the JSON, is not "
                                "explained with an \"APIs:\" line" % (name, x, y))
            elif not s.startswith("APIs: forbidden by the APIs: " + clause):
                problems.append("text: %s: pixel (%d, %d) should read \"APIs: forbidden by the "
                                "APIs: %s\", reads \"%s\"" % (name, x, y, clause, s))
    m = re.search(r"\ndepartures the graphics APIs forbid: (\d+) vectors?\n", text)
    if not m or int(m.group(1)) != len(forbidden):
        problems.append("text: the summary should read \"departures the graphics APIs forbid: "
                        "%d vector(s)\": %s" % (len(forbidden), m.group(0).strip() if m else
                                                "no such line"))
    return problems, sum(len(d) for d in forbidden.values())


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    recode, device, work = sys.argv[1], sys.argv[2], os.path.abspath(sys.argv[3])
    if device not in EXPECTED:
        fail("no expected table for the device %s (devices: %s)"
             % (device, ", ".join(sorted(EXPECTED))))
    expected = EXPECTED[device]
    os.makedirs(work, exist_ok=True)

    start = time.time()
    out = conform(recode, device, ["--json"])
    with open(os.path.join(work, "report.json"), "w", encoding="utf-8") as f:
        f.write(out)
    report = json.loads(out)
    json_s = time.time() - start
    results = report["results"]
    if not results or len(results) != report["vectors"]:
        fail("%d results for %s vectors" % (len(results), report["vectors"]))

    problems, forbidden, counts = check_json(report, expected)

    traits = {t["freedom"]: t for t in report.get("fingerprint", [])}
    tie = traits.get("tie rule")
    if tie is None:
        problems.append("the fingerprint has no \"tie rule\" trait: %s" % sorted(traits))
    elif tie.get("taken") != expected["tie rule"]:
        problems.append("the fingerprint's tie rule is taken as %s, expected %s (%s; candidates: "
                        "%s)" % (json.dumps(tie.get("taken")), expected["tie rule"],
                                 tie.get("verdict"),
                                 ", ".join("%s for %d against %d" % (c["reading"],
                                                                    c["pixels_for"],
                                                                    c["pixels_against"])
                                           for c in tie.get("candidates", []))))

    text_pixels = 0
    if forbidden:
        text_problems, text_pixels = check_text(recode, device, work, forbidden, counts)
        problems += text_problems
    total_s = time.time() - start

    for line in problems[:20]:
        print(line)
    if problems:
        fail("%d problems in recode conform --device %s's verdict against the graphics APIs "
             "(reports in %s)" % (len(problems), device, work))
    gone = sorted(set(expected["forbidden"]) - set(forbidden))
    print("native conform OK: %s: %d vectors in %.1f s (%.1f s in all): %d passed, %d failed; "
          "pixels the APIs forbid only in %s (%d pixels, each with its clause, %d in the text "
          "report)%s; tie rule taken: %s"
          % (device, len(results), json_s, total_s, report["passed"], report["failed"],
             ", ".join("%s (%d)" % (k, c[0]) for k, c in sorted(counts.items())) or "no vector",
             sum(c[0] for c in counts.values()), text_pixels,
             ("; expected but now within the APIs: " + ", ".join(gone)) if gone else "",
             expected["tie rule"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
