#!/usr/bin/python3
"""Checks the WebGPU back end (backends/webgpu) in a real browser: headless Chromium with
WebGPU, over DevTools. The page replays every golden vector of data/golden with the WGSL port of
the 32-bit contract shaders, the module preparing the proxy records (recode_gpu_commands), and
compares the depth and stencil aspects it reads back with the vector's expected buffers bit for
bit; then as many random command streams with sloped planes (webgpu_random_streams.py), against
the module's CPU device. Fails on any differing pixel, any console or WebGPU error, or a missing adapter.

Usage: check_webgpu_golden.py MODULE_JS GOLDEN_DIR WORKDIR [RANDOM_STREAMS]
       (RANDOM_STREAMS: how many random streams, seeds 1..N; default 200)
Exit status 0: passed; 1: failed; 77: skipped because no Chromium is installed.
"""

import json
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "apps"))
from check_explain_browser import (  # noqa: E402
    DevTools, chromium_and_fresh_workdir, fail, start_chromium)
from webgpu_page import write_page  # noqa: E402
from webgpu_random_streams import random_stream  # noqa: E402

# SwiftShader's WebGPU (Vulkan on the CPU) when no GPU is present; a GPU's when one is.
WEBGPU_FLAGS = ("--enable-unsafe-webgpu", "--enable-features=Vulkan")
TIMEOUT_S = 60
RANDOM_STREAMS = 200  # seeds 1..200


def run_async(dt, expression):
    """Evaluates an expression whose value is a promise, and returns what it resolves to."""
    r = dt.call("Runtime.evaluate", expression=expression, awaitPromise=True, returnByValue=True)
    if "exceptionDetails" in r:
        fail("evaluating " + expression[:60] + ": " +
             r["exceptionDetails"].get("exception", {}).get("description", json.dumps(r))[:500])
    return r["result"].get("value")


def main():
    if len(sys.argv) not in (4, 5):
        print(__doc__)
        return 2
    module_js, golden_dir, work = sys.argv[1], sys.argv[2], os.path.abspath(sys.argv[3])
    global RANDOM_STREAMS
    if len(sys.argv) == 5:
        RANDOM_STREAMS = int(sys.argv[4])
    chromium = chromium_and_fresh_workdir(work, "WebGPU")
    if chromium is None:
        return 77
    page = os.path.join(work, "webgpu.html")
    write_page(module_js, page)
    vectors = sorted(os.path.relpath(os.path.join(d, f), golden_dir)
                     for d, _, files in os.walk(golden_dir) for f in files if f.endswith(".json"))
    if not vectors:
        fail("no golden vectors in " + golden_dir)

    profile = tempfile.mkdtemp(prefix="recode-chromium-")
    proc, ws_url = start_chromium(chromium, profile, WEBGPU_FLAGS)
    try:
        dt = DevTools(ws_url)
        for domain in ("Runtime", "Log", "Network", "Page"):
            dt.call(domain + ".enable")
        dt.call("Page.navigate", url="file://" + page)
        dt.wait_event("Page.loadEventFired")
        run_async(dt, "recodeWebgpu.init(document.getElementById('wgsl').textContent)")
        adapter = dt.evaluate("recodeWebgpu.adapter")
        start = time.time()
        failed, records, gpu_ms = [], 0, 0.0

        def replay(name, text):
            nonlocal records, gpu_ms
            r = run_async(dt, "recodeWebgpu.runVector(%s)" % json.dumps(text))
            records += r["records"]
            gpu_ms += r["gpu_ms"]
            if r["depth_pixels"] or r["stencil_pixels"]:
                failed.append("%s: %d depth and %d stencil pixels differ, first %s"
                              % (name, r["depth_pixels"], r["stencil_pixels"],
                                 json.dumps(r["first_difference"])))

        for name in vectors:
            with open(os.path.join(golden_dir, name), encoding="utf-8") as f:
                replay(name, f.read())
        golden_failed = len(failed)
        elapsed = time.time() - start
        for seed in range(1, RANDOM_STREAMS + 1):
            replay("random stream %d" % seed, json.dumps(random_stream(seed)))
        random_elapsed = time.time() - start - elapsed
        if dt.problems():
            fail("console errors: " + "; ".join(dt.problems()[:5]))
    finally:
        proc.kill()
        shutil.rmtree(profile, ignore_errors=True)
    for line in failed[:20]:
        print(line)
    if failed:
        fail("%d of %d golden vectors and %d of %d random streams differ on WebGPU (%s)"
             % (golden_failed, len(vectors), len(failed) - golden_failed, RANDOM_STREAMS, adapter))
    print("webgpu golden OK: %d of %d vectors identical on WebGPU (adapter %s) in %.1f s, and "
          "%d of %d random streams in %.1f s; %d records, %.1f s drawing and reading back"
          % (len(vectors), len(vectors), adapter, elapsed, RANDOM_STREAMS, RANDOM_STREAMS,
             random_elapsed, records, gpu_ms / 1000))
    return 0


if __name__ == "__main__":
    sys.exit(main())
