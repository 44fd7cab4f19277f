#!/usr/bin/python3
"""Checks WebGPU's own depth/stencil pipeline under `recode conform` (the back end
backends/webgpu/native/native_backend.py: headless Chromium, SwiftShader where there is no GPU).

A native pipeline is not expected to pass: its rasterizer snaps to its own sub-pixel grid, owns
the samples on edges by its own rule and interpolates depth in float. What is checked is that it
runs the protocol and fails only where the APIs let it:

1. The sub-pixel grid, measured through the protocol itself: a triangle whose first vertex moves
   by 16, 8, ... 1/256 pixel on a steep plane; the finest move its depths follow is the grid.
   It must be 1/16 pixel or finer (Vulkan's least subPixelPrecisionBits, 4), as 2. assumes.
2. `recode conform --exec` over the golden vectors (or one shard of them) completes: every vector
   answered, none refused, at least one departing at a depth stage (float depth is not the
   contract's). The report's own verdict against the graphics APIs (docs/conformance.md, "What
   the graphics APIs allow") is held: no vector has a pixel the APIs forbid (`api.
   forbidden_pixels` is 0 or absent everywhere), and every vector whose depth the report calls
   required by the graphics APIs has the contract's depth.
3. The fingerprint's tie rule: the closest reading (most pixels for) is top_left_fill, WebGPU's
   (and Vulkan's and Direct3D's) fill rule, whether or not it is taken on every pixel.

Usage: check_webgpu_native_conform.py RECODE WORKDIR [SHARD]   (SHARD: I/N for --shard)
Exit status 0: passed; 1: failed; 77: skipped (no Chromium or no WebGPU adapter).
"""

import json
import os
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
BACKEND = os.path.join(ROOT, "backends", "webgpu", "native", "native_backend.py")
sys.path.insert(0, os.path.join(ROOT, "tests", "apps"))
from check_explain_browser import chromium_and_fresh_workdir, fail  # noqa: E402

NO_WEBGPU = ("navigator.gpu is missing", "no WebGPU adapter", "lacks depth32float-stencil8")
DEPTH_STAGES = ("depth value", "quantisation")
TIE_RULE = "top_left_fill"


def skip_without_webgpu(text):
    for reason in NO_WEBGPU:
        if reason in text:
            print("SKIP: %s in headless Chromium; WebGPU's native pipeline was not checked"
                  % reason)
            sys.exit(77)


def plane_q(vs, x, y):
    """The contract's depth (section 5) at pixel (x, y) of a triangle, 24 bits."""
    (X0, Y0, z0), (X1, Y1, z1), (X2, Y2, z2) = vs
    a2 = float((X1 - X0) * (Y2 - Y0) - (X2 - X0) * (Y1 - Y0))
    dzdx = ((z1 - z0) * (Y2 - Y0) - (z2 - z0) * (Y1 - Y0)) / a2
    dzdy = ((z2 - z0) * (X1 - X0) - (z1 - z0) * (X2 - X0)) / a2
    z = (z0 + dzdx * (256 * x + 128 - X0)) + dzdy * (256 * y + 128 - Y0)
    return round(min(max(z, 0.0), 1.0) * 16777215)


def subpixel_grid():
    """The finest move (in 1/256 pixel, a power of two) of a vertex that the pipeline's depth
    follows, with every coarser one followed too."""
    moves = (16, 8, 4, 2, 1)
    size = 16
    streams = [[[m, 0, 0.0], [size * 256, 0, 1.0], [0, size * 256, 0.5]] for m in moves]
    lines = [json.dumps({"protocol": "recode-conform-1"})]
    for k, vs in enumerate(streams):
        lines.append(json.dumps({"id": k + 1, "width": size, "height": size, "commands": [
            {"op": "depth_func", "func": "ALWAYS"},
            {"op": "draw", "vertices_fixed": vs, "indices": [0, 1, 2]}]}))
    r = subprocess.run([sys.executable, BACKEND], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, timeout=120)
    skip_without_webgpu(r.stderr)
    answers = [json.loads(line) for line in r.stdout.splitlines()]
    if r.returncode != 0 or len(answers) != len(lines):
        fail("the back end answered %d of %d messages, exit %d: %s"
             % (len(answers), len(lines), r.returncode, r.stderr[-2000:]))
    if answers[0].get("protocol") != "recode-conform-1" or "name" not in answers[0]:
        fail("the back end's greeting is " + json.dumps(answers[0]))
    grid = None
    for k, (m, vs) in enumerate(zip(moves, streams)):
        a = answers[k + 1]
        if a.get("id") != k + 1:
            fail("answer %d has id %s" % (k + 1, a.get("id")))
        errors = [abs(a["depth"][y * size + x] - plane_q(vs, x, y))
                  for y in range(size) for x in range(size)
                  if a["depth"][y * size + x] != 16777215]
        if not errors:
            fail("the probe triangle moved by %d/256 pixel drew nothing" % m)
        if max(errors) > 16:
            break
        grid = m
    if grid is None:
        fail("the pipeline's depth follows no vertex on the 1/16-pixel grid: it snaps to fewer "
             "than 4 sub-pixel bits, or the window coordinates do not reach it exactly")
    return grid, answers[0]["name"]


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__)
        return 2
    recode, work = sys.argv[1], os.path.abspath(sys.argv[2])
    shard = sys.argv[3] if len(sys.argv) == 4 else None
    if chromium_and_fresh_workdir(work, "WebGPU's native pipeline") is None:
        return 77

    start = time.time()
    grid, name = subpixel_grid()
    probe_s = time.time() - start
    cmd = [recode, "conform", "--exec", "%s %s" % (sys.executable, BACKEND), "--json"]
    if shard:
        cmd += ["--shard", shard]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
    conform_s = time.time() - start - probe_s
    skip_without_webgpu(r.stderr + r.stdout[:4096])
    if r.returncode not in (0, 2):
        fail("recode conform exited with %d: %s" % (r.returncode, (r.stderr + r.stdout)[-3000:]))
    report = json.loads(r.stdout)
    results = report["results"]
    if not results or len(results) != report["vectors"]:
        fail("%d results for %s vectors" % (len(results), report["vectors"]))
    if not report["backend"].startswith("WebGPU native"):
        fail("the back end is named " + report["backend"])

    problems = []
    stages = {}
    forbidden = depth_required = 0
    for v in results:
        name_ = v["file"]
        stage = v.get("stage")
        if v["status"] != "pass":
            stages[stage] = stages.get(stage, 0) + 1
        if stage == "validation":
            problems.append(name_ + ": refused by the back end")
        n = (v.get("api") or {}).get("forbidden_pixels", 0)
        if n:
            forbidden += 1
            first = [e for e in v.get("explained", [])
                     if not e.get("api", {}).get("allowed", True)]
            problems.append("%s: %d pixels the graphics APIs forbid (stage %s)%s"
                            % (name_, n, stage, ("; first: pixel (%d, %d): %s"
                                                 % (first[0]["x"], first[0]["y"],
                                                    first[0]["api"].get("clause")))
                               if first else ""))
        if v.get("required_by", {}).get("depth") == "graphics APIs":
            depth_required += 1
            if v.get("depth_pixels", 0):
                problems.append("%s: depth required by the APIs, but %d depth pixels differ"
                                % (name_, v["depth_pixels"]))
    if not any(stages.get(s) for s in DEPTH_STAGES):
        problems.append("no vector departs at a depth stage: is this really the native pipeline?")

    traits = {t["freedom"]: t for t in report.get("fingerprint", [])}

    def closest(trait):
        """The candidate readings of a fingerprint trait with the most pixels for, best first."""
        cands = traits.get(trait, {}).get("candidates", [])
        return sorted(cands, key=lambda c: -c["pixels_for"])

    tie = closest("tie rule")
    if not tie or tie[0]["reading"] != TIE_RULE or (
            len(tie) > 1 and tie[1]["pixels_for"] == tie[0]["pixels_for"]):
        problems.append("the fingerprint's tie rule: the closest reading should be %s, alone; "
                        "the candidates: %s" % (TIE_RULE, ", ".join(
                            "%s for %d against %d" % (c["reading"], c["pixels_for"],
                                                      c["pixels_against"]) for c in tie)
                            or "none"))
    subpixel = closest("sub-pixel precision")
    for line in problems[:20]:
        print(line)
    if problems:
        fail("%d problems on WebGPU's native pipeline (%s; %d vectors with pixels the APIs "
             "forbid)" % (len(problems), name, forbidden))
    print("webgpu native conform OK: %s; sub-pixel grid 1/%d pixel (probe %.1f s); %d vectors "
          "in %.1f s: %d passed, %d failed (by stage: %s); no pixel the graphics APIs forbid, the "
          "contract's depth on all %d whose depth the APIs require; fingerprint: tie rule closest "
          "%s (for %d, against %d; taken: %s), sub-pixel precision closest %s"
          % (name, 256 // grid, probe_s, len(results), conform_s, report["passed"],
             report["failed"], ", ".join("%s %d" % kv for kv in sorted(stages.items())),
             depth_required, tie[0]["reading"], tie[0]["pixels_for"], tie[0]["pixels_against"],
             json.dumps(traits["tie rule"].get("taken")),
             subpixel[0]["reading"] if subpixel else "none"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
