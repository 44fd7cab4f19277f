#!/usr/bin/python3
"""WebGPU's own depth/stencil pipeline as a `recode conform` back end (protocol recode-conform-1,
docs/conformance.md): one headless Chromium (WebGPU; SwiftShader where there is no GPU) for the
whole run, one page (native_page.html, native_pipeline.js beside this file), and for each request
the commands drawn by a native render pipeline: the browser's rasterizer decides coverage and
interpolates depth, the depth32float-stencil8 attachment's state does the tests and the ops.

    recode conform --exec "/usr/bin/python3 backends/webgpu/native/native_backend.py"

The one conversion that is this harness's and not WebGPU's: WebGPU cannot copy a depth24plus
texture out, so the depth is stored in depth32float and each value f read back is answered as
the 24-bit q = f * 16777215 rounded to nearest, ties to even (exact in double: f has 24
significant bits). Needs Debian's python3 with python3-websocket and Chromium; no network.
Exit status 1 (with the reason on stderr) when Chromium, WebGPU or the page fails.
"""

import array
import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "apps"))

# The protocol owns stdout: everything else printed (the DevTools helpers' failure lines
# included) goes to stderr, which `recode` quotes when the run fails.
PROTOCOL = os.fdopen(os.dup(1), "w", encoding="utf-8")
os.dup2(2, 1)
sys.stdout = sys.stderr

import check_explain_browser as browser  # noqa: E402  (DevTools over python3-websocket)

browser.TIMEOUT_S = 120  # per DevTools call: the largest vectors take seconds on SwiftShader
WEBGPU_FLAGS = ("--enable-unsafe-webgpu", "--enable-features=Vulkan")
DEPTH_MAX = 16777215


def die(message):
    sys.stderr.write("native_backend: " + message + "\n")
    sys.exit(1)


def send(message):
    PROTOCOL.write(json.dumps(message, separators=(",", ":")) + "\n")
    PROTOCOL.flush()


def run_async(dt, expression):
    """The value an expression's promise resolves to; an exception ends the back end."""
    r = dt.call("Runtime.evaluate", expression=expression, awaitPromise=True, returnByValue=True)
    if "exceptionDetails" in r:
        details = r["exceptionDetails"]
        die("the page threw: " +
            details.get("exception", {}).get("description", json.dumps(details))[:1000])
    return r["result"].get("value")


def depth24(f):
    """The harness's conversion of a depth32float value to 24 bits: round to nearest (Python's
    round is half to even) of f * 16777215, after clamping to [0, 1]."""
    return round(min(max(f, 0.0), 1.0) * DEPTH_MAX)


def answer(dt, message):
    w, h = message["width"], message["height"]
    r = run_async(dt, "recodeNative.run(%d, %d, %s)" % (w, h, json.dumps(message["commands"])))
    floats = array.array("f")
    floats.frombytes(base64.b64decode(r["depth"]))
    if sys.byteorder != "little":
        floats.byteswap()
    stencil = base64.b64decode(r["stencil"])
    if len(floats) != w * h or len(stencil) != w * h:
        die("the page answered %d depth and %d stencil values for %d x %d"
            % (len(floats), len(stencil), w, h))
    problems = dt.problems()
    if problems:
        die("WebGPU or the page reported: " + "; ".join(problems[:5]))
    return {"id": message["id"], "depth": [depth24(f) for f in floats], "stencil": list(stencil)}


def main():
    chromium = browser.find_chromium()
    if chromium is None:
        die("no chromium on PATH (scripts/setup.sh installs it)")
    profile = tempfile.mkdtemp(prefix="recode-webgpu-native-")
    proc = None
    try:
        proc, ws_url = browser.start_chromium(chromium, profile, WEBGPU_FLAGS)
        dt = browser.DevTools(ws_url)
        for domain in ("Runtime", "Log", "Page"):
            dt.call(domain + ".enable")
        dt.call("Page.navigate", url="file://" + os.path.join(HERE, "native_page.html"))
        dt.wait_event("Page.loadEventFired")
        info = run_async(dt, "recodeNative.init()")
        version = dt.evaluate("(navigator.userAgent.match(/Chrome\\/[0-9.]+/) || ['?'])[0]")
        name = "WebGPU native depth/stencil pipeline (%s, adapter %s, max texture %d)" % (
            version, info["adapter"], info["maxTexture"])
        for line in sys.stdin:
            message = json.loads(line)
            if "protocol" in message:
                send({"protocol": "recode-conform-1", "name": name[:200]})
                continue
            send(answer(dt, message))
    finally:
        if proc is not None:  # asked to end first, so that its children stop writing the profile
            proc.terminate()
            try:
                proc.wait(timeout=3)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        shutil.rmtree(profile, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
