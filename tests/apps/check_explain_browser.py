#!/usr/bin/python3
"""Checks `recode explain`'s page in a real browser: headless Chromium over the DevTools protocol.

Loads index.html from file://, fails on any console error, uncaught exception or failed resource
load, clicks a pixel that `recode pair --dump-cases` says is case 4, and compares what the ray
inspector then shows (the case, the depth and stencil after every step) with `recode pair --json
--pixel X,Y`, which reads the device one pixel at a time without the explain code. Then steps the
slider back with the keyboard, checks the highlighted step moved, and saves screenshots.

Usage: check_explain_browser.py RECODE WORKDIR
Exit status 0: passed; 1: failed; 77: skipped because no Chromium is installed.
"""

import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.request

RESOLUTION = "96"
TIMEOUT_S = 30


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def read_pgm(path):
    """A binary PGM (P5, maxval 255) as (width, height, rows top row first)."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos : pos + 1].isspace():
            pos += 1
        if data[pos : pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end : end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    pos += 1
    if fields[0] != b"P5":
        fail(path + " is not a binary PGM")
    w, h = int(fields[1]), int(fields[2])
    pixels = data[pos : pos + w * h]
    return w, h, [pixels[r * w : (r + 1) * w] for r in range(h)]


class DevTools:
    """One page target over the DevTools protocol: commands and the events seen so far."""

    def __init__(self, ws_url):
        import websocket  # python3-websocket (scripts/setup.sh)

        self.ws = websocket.create_connection(ws_url, timeout=TIMEOUT_S, suppress_origin=True)
        self.next_id = 0
        self.events = []

    def call(self, method, **params):
        self.next_id += 1
        my_id = self.next_id
        self.ws.send(json.dumps({"id": my_id, "method": method, "params": params}))
        deadline = time.time() + TIMEOUT_S
        while time.time() < deadline:
            message = json.loads(self.ws.recv())
            if message.get("id") == my_id:
                if "error" in message:
                    fail(method + ": " + json.dumps(message["error"]))
                return message.get("result", {})
            if "method" in message:
                self.events.append(message)
        fail(method + ": no answer within %d s" % TIMEOUT_S)

    def wait_event(self, method):
        deadline = time.time() + TIMEOUT_S
        while time.time() < deadline:
            for e in self.events:
                if e["method"] == method:
                    return e
            message = json.loads(self.ws.recv())
            if "method" in message:
                self.events.append(message)
        fail("no " + method + " within %d s" % TIMEOUT_S)

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        if "exceptionDetails" in r:
            fail("evaluating " + expression[:80] + ": " + json.dumps(r["exceptionDetails"]))
        return r["result"].get("value")

    def problems(self):
        """Console errors, uncaught exceptions and failed loads seen so far."""
        out = []
        for e in self.events:
            m, p = e["method"], e.get("params", {})
            if m == "Runtime.exceptionThrown":
                out.append("exception: " + json.dumps(p.get("exceptionDetails", {}))[:300])
            elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                out.append("console." + p["type"] + ": " + json.dumps(p.get("args"))[:300])
            elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
                out.append("log: " + p["entry"].get("text", ""))
            elif m == "Network.loadingFailed":
                out.append("failed load: " + p.get("errorText", "") + " " + p.get("requestId", ""))
        return out

    def screenshot(self, path, clip=None):
        params = {"format": "png"}
        if clip:
            params["clip"] = dict(clip, scale=1)
        r = self.call("Page.captureScreenshot", **params)
        with open(path, "wb") as f:
            f.write(base64.b64decode(r["data"]))


def chromium_and_fresh_workdir(work, what):
    """Chromium's path, with `work` emptied and made again; None, after printing the SKIP line
    the ctests look for, where no Chromium is installed."""
    chromium = find_chromium()
    if chromium is None:
        print("SKIP: no chromium on PATH (scripts/setup.sh installs it); %s was not checked" % what)
        return None
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    return chromium


def start_chromium(chromium, profile, gpu_flags=("--disable-gpu",)):
    """gpu_flags: the pages here need no GPU, unless a caller asks for one (WebGPU)."""
    args = [chromium, "--headless=new", "--no-sandbox", *gpu_flags, "--no-first-run",
            "--disable-extensions", "--remote-debugging-port=0", "--remote-allow-origins=*",
            "--user-data-dir=" + profile, "--window-size=1600,1000", "about:blank"]
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    port_file = os.path.join(profile, "DevToolsActivePort")
    deadline = time.time() + TIMEOUT_S
    while time.time() < deadline:
        if os.path.exists(port_file):
            lines = open(port_file).read().split("\n")
            if len(lines) >= 2 and lines[0].strip():
                port = int(lines[0])
                with urllib.request.urlopen("http://127.0.0.1:%d/json/list" % port) as r:
                    targets = json.loads(r.read())
                pages = [t for t in targets if t.get("type") == "page"]
                if pages:
                    return proc, pages[0]["webSocketDebuggerUrl"]
        if proc.poll() is not None:
            fail("chromium exited with status %d before opening DevTools" % proc.returncode)
        time.sleep(0.1)
    proc.kill()
    fail("chromium did not open DevTools within %d s" % TIMEOUT_S)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(" ".join(cmd) + " exited with %d: %s" % (r.returncode, r.stderr.strip()))
    return r.stdout


def first_pixel_of_case(pgm_path, wanted):
    w, h, rows = read_pgm(pgm_path)
    for top_row, row in enumerate(rows):
        for x, c in enumerate(row):
            if c == wanted:
                return x, h - 1 - top_row  # GL y: from the bottom
    return None


# Where to click framebuffer pixel (x, y): on the first picture showing it that the pointer can
# reach (the inspector panel may cover part of the page), case maps first.
CLICK_TARGET_JS = """
(function (x, y) {
  const all = Array.from(document.querySelectorAll('img[data-region]'));
  const ordered = all.filter(i => i.alt.startsWith('cases')).concat(
      all.filter(i => !i.alt.startsWith('cases')));
  for (const img of ordered) {
    const r = img.dataset.region.split(',').map(Number);
    if (x < r[0] || x >= r[2] || y < r[1] || y >= r[3]) continue;
    img.scrollIntoView({block: 'center'});
    const b = img.getBoundingClientRect();
    const cx = b.left + (x - r[0] + 0.5) * b.width / (r[2] - r[0]);
    const cy = b.top + (r[3] - 1 - y + 0.5) * b.height / (r[3] - r[1]);
    if (document.elementFromPoint(cx, cy) === img)
      return {file: img.getAttribute('src'), x: cx, y: cy};
  }
  return null;
})(%d, %d)
"""

INSPECTOR_JS = """
(function () {
  const rows = {};
  document.querySelectorAll('#inspector-passes tr[data-step]').forEach(function (tr) {
    rows[tr.dataset.step] = {depth: tr.querySelector('.depth').innerText,
                             stencil: tr.querySelector('.stencil').innerText,
                             now: tr.classList.contains('now')};
  });
  const c = document.getElementById('inspector-case');
  const t = document.getElementById('inspector-title');
  return {title: t ? t.innerText : '', kase: c ? c.innerText : '', rows: rows,
          bars: document.querySelectorAll('#ray-svg rect').length,
          stepName: document.getElementById('step-name').innerText};
})()
"""


def leading_int(text):
    digits = ""
    for ch in text.strip():
        if not ch.isdigit():
            break
        digits += ch
    if not digits:
        fail("expected a number at the start of " + repr(text))
    return int(digits)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    recode, work = sys.argv[1], os.path.abspath(sys.argv[2])
    chromium = chromium_and_fresh_workdir(work, "the page")
    if chromium is None:
        return 77
    page_dir = os.path.join(work, "page")

    # The oracle first, without the explain code: the case of every pixel, then one case-4
    # pixel's buffers after every step.
    pgm = os.path.join(work, "cases.pgm")
    run([recode, "pair", "--resolution", RESOLUTION, "--dump-cases", pgm, "--no-picture"])
    pixel = first_pixel_of_case(pgm, 4)
    if pixel is None:
        fail("the built-in pair at %s pixels has no case-4 pixel" % RESOLUTION)
    x, y = pixel
    expected = json.loads(run([recode, "pair", "--resolution", RESOLUTION, "--json",
                               "--no-timing", "--pixel", "%d,%d" % (x, y)]))["pixel"]
    if expected["case"] != 4:
        fail("pair --pixel says case %s at (%d, %d), --dump-cases 4" % (expected["case"], x, y))
    run([recode, "explain", "--resolution", RESOLUTION, "--out", page_dir])

    profile = tempfile.mkdtemp(prefix="recode-chromium-")
    proc, ws_url = start_chromium(chromium, profile)
    try:
        dt = DevTools(ws_url)
        for domain in ("Runtime", "Log", "Network", "Page"):
            dt.call(domain + ".enable")
        url = "file://" + os.path.join(page_dir, "index.html")
        dt.call("Page.navigate", url=url)
        dt.wait_event("Page.loadEventFired")
        if dt.evaluate("document.querySelectorAll('img[data-region]').length") < 1:
            fail("the page has no pictures with a data-region")
        broken = dt.evaluate(
            "Array.from(document.images).filter(i => !i.complete || i.naturalWidth === 0)"
            ".map(i => i.getAttribute('src'))")
        if broken:
            fail("pictures that did not load: " + ", ".join(broken))

        target = dt.evaluate(CLICK_TARGET_JS % (x, y))
        if target is None:
            fail("no picture shows pixel (%d, %d) where the pointer can reach it" % (x, y))
        print("clicking pixel (%d, %d) on %s" % (x, y, target["file"]))
        for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
            dt.call("Input.dispatchMouseEvent", type=kind, x=target["x"], y=target["y"],
                    button="left", clickCount=1)
        shown = dt.evaluate(INSPECTOR_JS)

        errors = []
        if shown["title"] != "pixel (%d, %d)" % (x, y):
            errors.append("inspector title %r, expected pixel (%d, %d)" % (shown["title"], x, y))
        if not shown["kase"].startswith("case 4:"):
            errors.append("inspector case %r, pair --pixel says 4" % shown["kase"])
        for step, want in expected["steps"].items():
            row = shown["rows"].get(step)
            if row is None:
                errors.append("no inspector row for step " + step)
                continue
            if leading_int(row["depth"]) != want["depth"]:
                errors.append("%s: depth %r, pair --pixel says %d" % (step, row["depth"],
                                                                      want["depth"]))
            if leading_int(row["stencil"]) != want["stencil"]:
                errors.append("%s: stencil %r, pair --pixel says %d" % (step, row["stencil"],
                                                                        want["stencil"]))
        if set(shown["rows"]) != set(expected["steps"]):
            errors.append("inspector steps %s, pair --pixel steps %s" %
                          (sorted(shown["rows"]), sorted(expected["steps"])))
        if shown["bars"] < 2:
            errors.append("the ray drawing shows %d interval bars, expected A's and B's"
                          % shown["bars"])
        dt.screenshot(os.path.join(work, "inspector-case4.png"))
        panel = dt.evaluate("(function () { const b = document.getElementById('inspector')"
                            ".getBoundingClientRect(); return {x: b.left + window.scrollX, y: b.top + window.scrollY, "
                            "width: b.width, height: b.height}; })()")
        dt.screenshot(os.path.join(work, "inspector-panel.png"), panel)

        # One step back with the keyboard: the highlighted row must move to the step before.
        steps = list(expected["steps"])
        before = [s for s, r in shown["rows"].items() if r["now"]]
        dt.call("Input.dispatchKeyEvent", type="keyDown", key="ArrowLeft", code="ArrowLeft",
                windowsVirtualKeyCode=37)
        dt.call("Input.dispatchKeyEvent", type="keyUp", key="ArrowLeft", code="ArrowLeft",
                windowsVirtualKeyCode=37)
        after_key = dt.evaluate(INSPECTOR_JS)
        after = [s for s, r in after_key["rows"].items() if r["now"]]
        if before != [steps[-1]] or after != [steps[-2]]:
            errors.append("slider: highlighted %s, then %s after ArrowLeft; expected %s then %s"
                          % (before, after, steps[-1], steps[-2]))
        if after_key["stepName"] == shown["stepName"]:
            errors.append("the step name did not change with ArrowLeft")
        dt.screenshot(os.path.join(work, "inspector-step-back.png"))

        errors += dt.problems()
        if errors:
            for e in errors:
                print("FAIL: " + e)
            return 1
        print("browser check OK: pixel (%d, %d) case 4, %d steps match recode pair --pixel; "
              "screenshots in %s" % (x, y, len(expected["steps"]), work))
        return 0
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
