#!/usr/bin/python3
"""Checks `recode explain --interactive`'s page in a real browser (headless Chromium, DevTools).

Loads the page from file:// with no console error, waits for the WebAssembly module's first
answer, drags a picture (moving block B), exports the scene with the page's button, and requires
the page's verdict, case counts and whole `recode pair` object to equal the native `recode pair
--json` on the exported file. Then a second pose through the page's controls (B's position and
the MOR mode), checked the same way. B's position fields show where B is after the slider and
Play (the scene the page runs has B there, and Export saves it), and a position typed with the
slider off centre places B there. Choosing the shape obj with no file says that block B needs an
OBJ file. Saves screenshots, and reports the time of one update at
256 and 512 pixels as the page measures it (reported, not judged).

Usage: check_interactive_browser.py RECODE WORKDIR
Exit status 0: passed; 1: failed; 77: skipped because no Chromium is installed.
"""

import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "apps"))
from check_explain_browser import (  # noqa: E402
    DevTools, chromium_and_fresh_workdir, fail, start_chromium)

TIMEOUT_S = 60
TIMING_KEYS = {"timing_us", "timing_steps_us"}


def strip(j):
    """The pair object without its wall-clock fields and its source (a path on either side)."""
    if isinstance(j, dict):
        return {k: strip(v) for k, v in j.items() if k not in TIMING_KEYS and k != "source"}
    if isinstance(j, list):
        return [strip(v) for v in j]
    return j


def settle(dt, updates_before):
    """Waits until the page has run an update after `updates_before` and has nothing pending."""
    deadline = time.time() + TIMEOUT_S
    while time.time() < deadline:
        s = dt.evaluate("({u: recodePage.metrics.updates, p: recodePage.pending(),"
                        " e: recodePage.error})")
        if s["e"]:
            fail("the page reports an error: " + s["e"])
        if s["u"] > updates_before and not s["p"]:
            return s["u"]
        time.sleep(0.05)
    fail("the page did not update within %d s" % TIMEOUT_S)


def write_page(recode, page_dir):
    """`recode explain --interactive --out page_dir`; the path of the index.html it wrote."""
    r = subprocess.run([recode, "explain", "--interactive", "--out", page_dir],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail("recode explain --interactive: " + r.stderr.strip())
    return os.path.join(page_dir, "index.html")


def open_page(dt, index_html, downloads=None):
    """Opens the page from file://, waits for the module's first answer and the update after
    it, and requires a clean console; returns the page's update count."""
    for domain in ("Runtime", "Log", "Network", "Page"):
        dt.call(domain + ".enable")
    if downloads:
        dt.call("Page.setDownloadBehavior", behavior="allow", downloadPath=downloads)
    dt.call("Page.navigate", url="file://" + index_html)
    dt.wait_event("Page.loadEventFired")
    deadline = time.time() + TIMEOUT_S
    while not dt.evaluate("!!(window.recodePage && recodePage.ready)"):
        if time.time() > deadline:
            fail("the page's module did not answer within %d s" % TIMEOUT_S)
        time.sleep(0.1)
    updates = settle(dt, 0)
    if dt.problems():
        fail("on load: " + "; ".join(dt.problems()))
    return updates


SHOWN_JS = """
(function () {
  const counts = {};
  document.querySelectorAll('#case-counts td[data-case]').forEach(function (td) {
    counts[td.dataset.case] = Number(td.textContent);
  });
  return {verdict: document.getElementById('live-verdict').textContent, counts: counts,
          pair: recodePage.pair, mor: document.getElementById('mor').value};
})()
"""


def export_scene(dt, downloads, name):
    """Clicks Export and returns the path of the scene file the browser saved."""
    for f in os.listdir(downloads):
        os.remove(os.path.join(downloads, f))
    dt.evaluate("document.getElementById('export').click()")
    target = os.path.join(downloads, "scene.json")
    deadline = time.time() + TIMEOUT_S
    while time.time() < deadline:
        if os.path.exists(target) and not any(f.endswith(".crdownload") for f in os.listdir(downloads)):
            kept = os.path.join(os.path.dirname(downloads), name)
            shutil.copy(target, kept)
            return kept
        time.sleep(0.05)
    fail("the Export button saved no scene.json within %d s" % TIMEOUT_S)


def compare_with_native(recode, dt, scene, what):
    shown = dt.evaluate(SHOWN_JS)
    r = subprocess.run([recode, "pair", scene, "--mor", shown["mor"], "--json", "--no-timing"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail("recode pair %s: %s" % (scene, r.stderr.strip()))
    native = json.loads(r.stdout)
    errors = []
    want_verdict = "collide" if native["collide"] else "apart"
    if shown["verdict"] != want_verdict:
        errors.append("verdict %r, recode pair says %r" % (shown["verdict"], want_verdict))
    want_counts = {k: int(v) for k, v in native["case_counts"].items()}
    if shown["counts"] != want_counts:
        errors.append("case counts %s, recode pair says %s" % (shown["counts"], want_counts))
    if strip(shown["pair"]) != strip(native):
        errors.append("the page's pair object differs from recode pair --json")
    if errors:
        fail(what + ": " + "; ".join(errors))
    print("%s: %s, case counts %s, the page equals recode pair on %s"
          % (what, shown["verdict"], " ".join("%s:%d" % kv for kv in sorted(want_counts.items())),
             os.path.basename(scene)))
    return native


FIELDS_JS = """
(function () {
  const fields = ['x', 'y', 'z'].map(function (a) {
    return Number(document.getElementById('pos-B-' + a).value);
  });
  const b = JSON.parse(recodePage.sceneText()).objects[1];
  return {fields: fields, scene: b.position, sweep: recodePage.state.sweep};
})()
"""


def b_fields_match(dt, what):
    """B's position fields show where B is: the position the scene file (what Export saves and
    the page runs) gives it."""
    got = dt.evaluate(FIELDS_JS)
    if any(abs(f - s) > 1e-9 for f, s in zip(got["fields"], got["scene"])):
        fail("%s: B's position fields show %s, the scene the page runs and exports has B at %s "
             "(slider at %s)" % (what, got["fields"], got["scene"], got["sweep"]))
    return got


def check_sweep_fields(dt, downloads, updates):
    """The slider and Play move B; its position fields follow, a position typed places B there,
    and Export saves the pose the fields show."""
    dt.evaluate("(function () { const s = document.getElementById('sweep'); s.value = '0.5';"
                " s.dispatchEvent(new Event('input')); })()")
    updates = settle(dt, updates)
    moved = b_fields_match(dt, "after the slider")
    if moved["sweep"] != 0.5:
        fail("the slider did not move B: the page's sweep is %s" % moved["sweep"])
    exported = json.load(open(export_scene(dt, downloads, "pose-3-slider.json")))
    if exported["objects"][1]["position"] != moved["scene"]:
        fail("Export saved B at %s, its fields show %s"
             % (exported["objects"][1]["position"], moved["fields"]))
    # Play for a few updates, then Stop.
    dt.evaluate("document.getElementById('play').click(); 0")
    deadline = time.time() + TIMEOUT_S
    while dt.evaluate("recodePage.metrics.updates") < updates + 5:
        if time.time() > deadline:
            fail("Play ran no update within %d s" % TIMEOUT_S)
        time.sleep(0.05)
    dt.evaluate("document.getElementById('play').click(); 0")
    updates = settle(dt, updates)
    played = b_fields_match(dt, "after Play")
    if played["sweep"] == moved["sweep"]:
        fail("Play did not move B: the sweep stayed at %s" % played["sweep"])
    # A position typed while the slider is off centre: B is where the field says.
    dt.evaluate("(function () { const z = document.getElementById('pos-B-z'); z.value = '3.25';"
                " z.dispatchEvent(new Event('change')); })()")
    updates = settle(dt, updates)
    typed = b_fields_match(dt, "after typing B's z")
    if typed["scene"][2] != 3.25:
        fail("B's z typed as 3.25 with the slider at %s runs B at z %s"
             % (typed["sweep"], typed["scene"][2]))
    print("B's position fields follow the slider (%s) and Play (%s), a typed z places B there; "
          "Export saves what they show" % (moved["fields"], played["fields"]))
    return updates


def check_obj_without_file(dt, updates):
    """Choosing the shape obj without a file says what is missing instead of silently keeping
    the last shape; choosing a shape again runs it."""
    dt.evaluate("(function () { const s = document.getElementById('shape-B'); s.value = 'obj';"
                " s.dispatchEvent(new Event('change')); })()")
    deadline = time.time() + TIMEOUT_S
    while True:
        e = dt.evaluate("(function () { const e = document.getElementById('live-error');"
                        " return {hidden: e.hidden, text: e.textContent,"
                        " pending: recodePage.pending()}; })()")
        if not e["pending"] and not e["hidden"]:
            break
        if time.time() > deadline:
            fail("shape obj without a file: no message within %d s (the page shows %r)"
                 % (TIMEOUT_S, e))
        time.sleep(0.05)
    if "Block B" not in e["text"] or "OBJ file" not in e["text"]:
        fail("shape obj without a file: the message %r does not say that block B needs an OBJ "
             "file" % e["text"])
    dt.evaluate("(function () { const s = document.getElementById('shape-B'); s.value = 'cone';"
                " s.dispatchEvent(new Event('change')); })()")
    # The message stays until the next run (settle() would take it for a new error): wait for
    # the cone's update, which must clear it.
    deadline = time.time() + TIMEOUT_S
    while (dt.evaluate("recodePage.metrics.updates") <= updates
           or dt.evaluate("recodePage.pending()")):
        if time.time() > deadline:
            fail("after choosing the cone again the page did not update within %d s" % TIMEOUT_S)
        time.sleep(0.05)
    after = dt.evaluate("({error: recodePage.error, hidden: document.getElementById("
                        "'live-error').hidden, updates: recodePage.metrics.updates})")
    if after["error"] or not after["hidden"]:
        fail("after choosing the cone again the message stays: %r" % after["error"])
    updates = after["updates"]
    print("shape obj without a file: %r" % e["text"])
    return updates


def timing(dt, resolution, runs=7):
    dt.evaluate("(function () { const s = document.getElementById('resolution'); s.value = '%d';"
                " s.dispatchEvent(new Event('change')); })()" % resolution)
    settle(dt, dt.evaluate("recodePage.metrics.updates") - 1)
    ms, module_ms = [], []
    for _ in range(runs):
        dt.evaluate("recodePage.update()")
        ms.append(dt.evaluate("recodePage.metrics.lastMs"))
        module_ms.append(dt.evaluate("recodePage.metrics.moduleMs"))
    return statistics.median(ms), statistics.median(module_ms)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    recode, work = sys.argv[1], os.path.abspath(sys.argv[2])
    chromium = chromium_and_fresh_workdir(work, "the interactive page")
    if chromium is None:
        return 77
    downloads = os.path.join(work, "downloads")
    os.makedirs(downloads)
    index_html = write_page(recode, os.path.join(work, "page"))
    size = os.path.getsize(index_html)

    profile = tempfile.mkdtemp(prefix="recode-chromium-")
    proc, ws_url = start_chromium(chromium, profile)
    try:
        dt = DevTools(ws_url)
        updates = open_page(dt, index_html, downloads)
        dt.screenshot(os.path.join(work, "loaded.png"))
        first = compare_with_native(recode, dt, export_scene(dt, downloads, "pose-0.json"),
                                    "as loaded")

        # Drag the first picture 40 CSS pixels right and 30 down: block B moves in the image plane.
        box = dt.evaluate("(function () { const c = document.querySelector('#live-result canvas');"
                          " c.scrollIntoView({block: 'center'}); const b = c.getBoundingClientRect();"
                          " return {x: b.left + b.width / 2, y: b.top + b.height / 2}; })()")
        x, y = box["x"], box["y"]
        dt.call("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left",
                buttons=1, clickCount=1)
        for k in range(1, 11):
            dt.call("Input.dispatchMouseEvent", type="mouseMoved", x=x + 4 * k, y=y + 3 * k,
                    button="left", buttons=1)
            time.sleep(0.03)
        dt.call("Input.dispatchMouseEvent", type="mouseReleased", x=x + 40, y=y + 30,
                button="left", buttons=0, clickCount=1)
        updates = settle(dt, updates)
        dt.screenshot(os.path.join(work, "dragged.png"))
        dragged_scene = export_scene(dt, downloads, "pose-1-dragged.json")
        if json.load(open(dragged_scene)) == json.load(open(os.path.join(work, "pose-0.json"))):
            fail("the drag did not move a block: the exported scene is the one as loaded")
        second = compare_with_native(recode, dt, dragged_scene, "after the drag")

        # A second pose through the controls: B's position along z and the MOR mode.
        dt.evaluate("(function () { const z = document.getElementById('pos-B-z'); z.value = '3.5';"
                    " z.dispatchEvent(new Event('change')); const m = document.getElementById('mor');"
                    " m.value = 'max'; m.dispatchEvent(new Event('change')); })()")
        updates = settle(dt, updates)
        dt.screenshot(os.path.join(work, "controls.png"))
        third = compare_with_native(recode, dt, export_scene(dt, downloads, "pose-2-controls.json"),
                                    "after the controls")
        if first == second or second == third:
            fail("two poses gave the same answer: the poses did not change what the page ran")
        updates = check_sweep_fields(dt, downloads, updates)
        updates = check_obj_without_file(dt, updates)
        if dt.problems():
            fail("console errors: " + "; ".join(dt.problems()))

        t256 = timing(dt, 256)
        t512 = timing(dt, 512)
        print("update time (median of 7, in the page): 256 px %.1f ms (module %.1f ms), "
              "512 px %.1f ms (module %.1f ms); page %d bytes" % (t256 + t512 + (size,)))
    finally:
        proc.kill()
        shutil.rmtree(profile, ignore_errors=True)
    print("interactive page OK: 3 poses equal recode pair, screenshots in " + work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
