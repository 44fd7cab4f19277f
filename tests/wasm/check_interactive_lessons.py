#!/usr/bin/python3
"""Checks that `recode explain --interactive`'s page teaches on its own, in headless Chromium.

The exercises on the geometry (page/predict.js, those with an `ask` list): no depths are given;
the reference's own depths at the pixel equal the blocks' numbers (a box's faces along the view
axis) and `recode pair --pixel`'s A depths; its MOR in each mode and its box test equal `recode
pair`'s. Each exercise accepts the reference's answers (depths off by less than the tolerance
the page states) and refuses, naming the step, each of: a depth taken from the wrong face, the
near and far ends swapped, a depth one unit off and one twice the tolerance off, a pixel counted
outside a MOR mode that examines it, the box test applied where the ranges meet (or not applied
where they do not), and each pass's value taken from a wrong pass. A wrong pass's feedback says
its rule and the inputs it tested as the student gave them, and shows its pictures only when
asked.

The page on its own: every term of a list (the MOR and its modes, the box test, each pass, the
read-back, the stencil encoding, the case table) has a definition on the page; every link is an
anchor of the page; no text of the page (exercises, feedback and rules included) points at a
file (docs/, .md); a picture an exercise names is one the page shows; the feedback's step names
are the form's.

The inspector and the layout: after a pixel pinned by a click, an exercise's inspector shows
the exercise's pixel at open and after a solve, and no pixel once the exercise is left; an answer the browser refuses clears the
verdict before it; leaving an exercise restores the pose it replaced; a pose change that closes
an exercise says so; at 800 and 1400 pixels wide the inspector covers no text or picture. The
3-D view's depth scale marks the view axis's coordinate. The page is under 3 MB; the time of a
redraw after a drag at 256 pixels is reported (measured, not judged: this machine is shared).

Usage: check_interactive_lessons.py RECODE WORKDIR
Exit status 0: passed; 1: failed; 77: skipped because no Chromium is installed.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "apps"))
sys.path.insert(0, HERE)
from check_explain_browser import (  # noqa: E402
    DevTools, chromium_and_fresh_workdir, fail, start_chromium)
from check_interactive_browser import open_page, settle, write_page  # noqa: E402
from check_interactive_teaching import (  # noqa: E402
    broken, click_pixel, drag_timing, native_pixel)

MAX_PAGE_BYTES = 3 * 1024 * 1024
DEPTH_ONE = 16777215

# The algorithm's terms: each must have its definition on the page, under this anchor.
TERMS = {"term-mor": "MOR", "term-mor-min": "MOR min", "term-mor-max": "MOR max",
         "term-mor-full": "MOR full", "term-box-test": "box test",
         "term-pass-1": "1 SetZ", "term-pass-2": "2 TestZ", "term-pass-3": "3 Load Amin",
         "term-pass-4": "4 B front vs Amin", "term-pass-5": "5 B back vs Amin",
         "term-read-back": "6 Read stencil", "term-stencil-encoding": "stencil encoding",
         "term-cases": "the nine cases", "term-entry-exit": "entry and exit",
         "term-depth": "depth", "term-stencil": "stencil", "term-view-axis": "view axis"}

PAGE_TEXT_JS = """
(function () {
  const bad = [];
  document.querySelectorAll('a[href]').forEach(function (a) {
    const h = a.getAttribute('href');
    if (h.charAt(0) !== '#' || !document.getElementById(h.slice(1))) bad.push(h);
  });
  const text = document.body.innerText;
  const files = text.match(/[\\w./-]*(docs\\/|\\.md\\b)[\\w./-]*/g) || [];
  return {bad: bad, files: files};
})()
"""


def page_refs(dt, where):
    """Fails on a link that is not an anchor of the page, or text naming a file outside it."""
    r = dt.evaluate(PAGE_TEXT_JS)
    if r["bad"]:
        fail("%s: links that are not anchors of the page: %s" % (where, r["bad"][:5]))
    if r["files"]:
        fail("%s: the page's text points at files outside it: %s" % (where, r["files"][:5]))


def check_terms(dt):
    got = dt.evaluate("(%s).map(function (id) { const dt = document.getElementById(id);"
                      " const dd = dt && dt.nextElementSibling; return {id: id, name: dt ?"
                      " dt.textContent : null, text: dd && dd.tagName === 'DD' ?"
                      " dd.textContent : ''}; })" % json.dumps(sorted(TERMS)))
    for t in got:
        if t["name"] is None or TERMS[t["id"]].lower() not in t["name"].lower():
            fail("the term %r has no entry %s on the page (found %r)"
                 % (TERMS[t["id"]], t["id"], t["name"]))
        if len(t["text"].split()) < 8:
            fail("the term %r has no definition on the page: %r" % (TERMS[t["id"]], t["text"]))
    cases = dt.evaluate("Array.from({length: 9}, function (_, c) { const r ="
                        " document.getElementById('term-case-' + c); return r ?"
                        " r.textContent : null; })")
    if any(c is None for c in cases):
        fail("the case table on the page lacks rows: %s" % cases)
    print("terms: %d defined on the page, the case table's 9 rows" % len(got))


def native_pair(recode, work, dt, mor):
    st = dt.evaluate("({text: recodePage.sceneText(), boxTest: recodePage.state.boxTest})")
    path = os.path.join(work, "lesson-scene.json")
    with open(path, "w") as f:
        f.write(st["text"])
    cmd = [recode, "pair", path, "--mor", mor, "--json", "--no-timing"]
    if not st["boxTest"]:
        cmd.append("--no-box-test")
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(" ".join(cmd) + ": " + r.stderr.strip())
    return json.loads(r.stdout)


def box_ends(block):
    """A box's near and far ends along z (the exercises look along z): [z + sz/2, z - sz/2]."""
    z, sz = block["position"][2], block["sizes"]["size"][2]
    return [z + sz / 2, z - sz / 2]


FILL_JS = """
(function (a) {
  const set = function (id, v) { const n = document.getElementById(id); if (n) n.value = v; };
  ['depth', 'range'].forEach(function (w) {
    ['A', 'B'].forEach(function (n) {
      const d = a[w === 'depth' ? 'depths' : 'ranges'];
      const none = document.getElementById('predict-' + w + '-' + n + '-none');
      const on = d && d[n] === null;
      if (none && none.checked !== on) { none.checked = on; none.dispatchEvent(new Event('change')); }
      if (d && d[n]) { set('predict-' + w + '-' + n + '-near', String(d[n][0]));
                       set('predict-' + w + '-' + n + '-far', String(d[n][1])); }
    });
  });
  ['min', 'max', 'full'].forEach(function (m) {
    const c = document.getElementById('predict-mor-' + m); if (c && a.mor) c.checked = a.mor[m];
  });
  if (a.box !== undefined) set('predict-box', a.box);
  if (a.stencil) a.stencil.forEach(function (v, k) { set('predict-stencil-' + (k + 1), String(v)); });
  if (a.kase !== undefined) set('predict-case', String(a.kase));
  document.getElementById('predict-check').click();
  const v = document.getElementById('predict-verdict');
  const r = document.getElementById('predict-rule');
  const i = document.getElementById('predict-inputs-used');
  return {verdict: v ? v.textContent : null, right: v ? v.className === 'right' : null,
          rule: r ? r.textContent : null, inputs: i ? i.textContent : null,
          button: !!document.getElementById('predict-show-section'),
          shown: Array.from(document.querySelectorAll('#live-result section.shown'))
            .filter(function (s) { return s.offsetParent !== null; })
            .map(function (s) { return s.id; })};
})(%s)
"""


def submit(dt, answers):
    return dt.evaluate(FILL_JS % json.dumps(answers))


def refused(e, v, what, words):
    if v["right"] or v["verdict"] is None or any(w not in v["verdict"] for w in words):
        fail("exercise %s: %s gave %r, not a refusal naming %s" % (e["id"], what, v["verdict"],
                                                                   words))


def start(dt, eid):
    updates = dt.evaluate("recodePage.metrics.updates")
    dt.evaluate("recodePredict.start(%s); 0" % json.dumps(eid))
    settle(dt, updates)
    cur = dt.evaluate("(function () { const c = recodePredict.current(); return c && {pixel:"
                      " c.pixel, truth: c.truth, i: c.index}; })()")
    if not cur:
        fail("exercise %s did not open" % eid)
    return cur


def check_geometry_exercise(recode, work, dt, e, tol):
    cur = start(dt, e["id"])
    t = cur["truth"]
    ask = e["ask"]
    right = {}
    blocks = {b["name"]: b for b in e["blocks"]}
    # The reference's own values against the blocks' numbers and the native program.
    if "depths" in ask:
        x, y = cur["pixel"]
        n_stencil, n_case = native_pixel(recode, work, dt, x, y)
        if n_stencil != t["stencil"] or n_case != t["kase"] or t["kase"] != e["want"]:
            fail("exercise %s at (%d, %d): the page's %s case %d, recode pair --pixel's %s case "
                 "%d, the exercise's case %s" % (e["id"], x, y, t["stencil"], t["kase"],
                                                 n_stencil, n_case, e["want"]))
        for n in "AB":
            if t["depths"][n] is None:
                fail("exercise %s: block %s is not on the chosen pixel's ray" % (e["id"], n))
            want = box_ends(blocks[n])
            if any(abs(a - b) > 1e-4 for a, b in zip(t["depths"][n], want)):
                fail("exercise %s: the reference's depths of %s are %s, its box spans %s"
                     % (e["id"], n, t["depths"][n], want))
        right["depths"] = {n: box_ends(blocks[n]) for n in "AB"}
        # recode pair --pixel's depth after SetZ is Amax, after Load Amin it is Amin.
        r = json.loads(subprocess.run(
            [recode, "pair", os.path.join(work, "exercise-scene.json"), "--mor", e["mor"],
             "--json", "--no-timing", "--pixel", "%d,%d" % (x, y)],
            capture_output=True, text=True).stdout)
        dmin, dmax = r["frame"]["depth_range"]
        steps = r["pixel"]["steps"]
        a_native = [dmax - steps[k]["depth"] / DEPTH_ONE * (dmax - dmin)
                    for k in ("load_amin", "set_z")]
        if any(abs(a - b) > 1e-5 for a, b in zip(a_native, t["depths"]["A"])):
            fail("exercise %s: A's depths %s, recode pair --pixel's %s"
                 % (e["id"], t["depths"]["A"], a_native))
    if "ranges" in ask:
        for n in "AB":
            if any(abs(a - b) > 1e-9 for a, b in zip(t["ranges"][n], box_ends(blocks[n]))):
                fail("exercise %s: the range of %s is %s, its box spans %s"
                     % (e["id"], n, t["ranges"][n], box_ends(blocks[n])))
        right["ranges"] = {n: box_ends(blocks[n]) for n in "AB"}
    if "mor" in ask:
        x, y = cur["pixel"]
        for m in ("min", "max", "full"):
            r = native_pair(recode, work, dt, m)["mor"]
            inside = r[0] <= x < r[2] and r[1] <= y < r[3]
            if inside != t["mor"][m]:
                fail("exercise %s: MOR %s %s pixel (%d, %d) on the page, recode pair's MOR is %s"
                     % (e["id"], m, "has" if t["mor"][m] else "lacks", x, y, r))
        right["mor"] = t["mor"]
    if "boxtest" in ask:
        native = native_pair(recode, work, dt, e["mor"])
        if native["boxes_overlap"] == t["boxStops"]:
            fail("exercise %s: the page's box test %s, recode pair's boxes_overlap is %s"
                 % (e["id"], "stops" if t["boxStops"] else "runs", native["boxes_overlap"]))
        right["box"] = "stops" if t["boxStops"] else "runs"
    if "passes" in ask:
        right["stencil"], right["kase"] = t["stencil"], t["kase"]
        if t["kase"] != e["want"]:
            fail("exercise %s: case %d, the exercise is about case %s"
                 % (e["id"], t["kase"], e["want"]))
    kinds = []
    # Typical wrong depths (or ranges): each refused, naming the block and the mistake.
    for what in ("depths", "ranges"):
        if what not in right:
            continue
        for n in "AB":
            near, far = right[what][n]
            wrongs = [("swapped", [far, near], ["swapped", n]),
                      ("wrong face", [far, far], ["wrong face", n]),
                      ("one unit off", [near + 1, far], [n]),
                      ("twice the tolerance off", [near, far - 2 * tol], [n])]
            for kind, given, words in wrongs:
                a = json.loads(json.dumps(right))
                a[what][n] = given
                refused(e, submit(dt, a), "%s of %s %s" % (what, n, kind), words)
                kinds.append(kind)
    if "mor" in right:
        for m in ("min", "max", "full"):
            a = json.loads(json.dumps(right))
            a["mor"][m] = not right["mor"][m]
            refused(e, submit(dt, a), "MOR %s flipped" % m, ["MOR " + m])
            kinds.append("counted %s MOR %s" % ("outside" if right["mor"][m] else "inside", m))
    if "box" in right:
        a = dict(right, box="runs" if right["box"] == "stops" else "stops")
        refused(e, submit(dt, a), "the box test the other way", ["Box test"])
        kinds.append("box test " + a["box"])
    if "stencil" in right:
        titles = dt.evaluate("recodePredict.passes.map(function (p) { return p.title; })")
        form_rows = dt.evaluate("Array.from(document.querySelectorAll('#predict-form td:first-"
                                "child')).map(function (td) { return td.textContent; })")
        for k in range(5):
            a = dict(right, stencil=broken(right["stencil"], k))
            v = submit(dt, a)
            refused(e, v, "pass %d from a wrong pass" % (k + 1), [titles[k]])
            if not any(titles[k] in row for row in form_rows):
                fail("exercise %s: the feedback names %r, no row of the form does (%s)"
                     % (e["id"], titles[k], form_rows))
            if k > 0 and ("stencil before it: %d " % a["stencil"][k - 1]) not in (v["inputs"] or ""):
                fail("exercise %s: a wrong pass %d's feedback does not show the stencil it "
                     "tested (%d): %r" % (e["id"], k + 1, a["stencil"][k - 1], v["inputs"]))
            if v["shown"]:
                fail("exercise %s: a wrong pass %d showed its pictures before being asked: %s"
                     % (e["id"], k + 1, v["shown"]))
            if k == 3:
                if not v["button"]:
                    fail("exercise %s: no button to show pass 4's pictures" % e["id"])
                shown = dt.evaluate("document.getElementById('predict-show-section').click();"
                                    " Array.from(document.querySelectorAll('#live-result"
                                    " section.shown')).filter(function (s) { return"
                                    " s.offsetParent !== null; }).map(function (s) {"
                                    " return s.id; })")
                if shown != ["test_amin_front"]:
                    fail("exercise %s: asking for pass 4's pictures showed %s"
                         % (e["id"], shown))
        kinds.append("each pass")
        a = dict(right, kase=(right["kase"] + 1) % 9 if right["kase"] >= 0 else 0)
        v = submit(dt, a)
        refused(e, v, "a wrong case", ["6 Read stencil"])
        if not any("6 Read stencil" in row for row in form_rows):
            fail("exercise %s: the feedback names 6 Read stencil, the form's rows are %s"
                 % (e["id"], form_rows))
    # The reference's answers, with each depth read a little off (within the tolerance).
    a = json.loads(json.dumps(right))
    for what in ("depths", "ranges"):
        if what in a:
            for n in "AB":
                a[what][n] = [a[what][n][0] + tol / 2, a[what][n][1] - tol / 2]
    v = submit(dt, a)
    if not v["right"]:
        fail("exercise %s: the reference's answers %s were refused: %r"
             % (e["id"], a, v["verdict"]))
    print("exercise %-11s %s accepted; refused by name: %s"
          % (e["id"], ", ".join(sorted(right)), ", ".join(kinds)))
    return cur


def leave(dt, before):
    """Leaves the open exercise; the page must come back to the pose `before` (a signature)."""
    dt.evaluate("document.getElementById('predict-close').click(); 0")
    deadline = time.time() + 10
    while dt.evaluate("recodePage.signature()") != before or dt.evaluate("recodePage.pending()"):
        if time.time() > deadline:
            fail("leaving the exercise kept its pose instead of the one it replaced")
        time.sleep(0.05)


def inspector_pixel(dt):
    return dt.evaluate("(function () { const t = document.getElementById('inspector-title');"
                       " return {pixel: recodeInspector.pixel(), title: t ? t.textContent : null,"
                       " visible: document.getElementById('inspector').getClientRects().length"
                       " > 0};"
                       " })()")


def check_inspector(dt):
    """A pixel pinned by a click before an exercise never shows in the exercise's inspector."""
    # Pin a pixel of the default pose at 64 pixels (a picture pixel is several screen pixels)
    # by a click on its first picture.
    updates = dt.evaluate("recodePage.metrics.updates")
    dt.evaluate("recodePage.load({resolution: 64}); 0")
    settle(dt, updates)
    target = dt.evaluate("(function () { const d = recodePage.rayData; const w = d.crop[2] -"
                         " d.crop[0]; return [d.crop[0] + 3, d.crop[1] + 2]; })()")
    click_pixel(dt, "#live-result canvas[data-region]", *target)
    got = inspector_pixel(dt)
    if got["pixel"] != target:
        fail("a click did not pin pixel %s in the inspector: %s" % (target, got))
    before = dt.evaluate("recodePage.signature()")
    cur = start(dt, "touching")
    got = inspector_pixel(dt)
    if got["pixel"] != cur["pixel"] or got["title"] != "pixel (%d, %d)" % tuple(cur["pixel"]):
        fail("exercise touching opened at pixel %s, the inspector shows %s (pinned before: %s)"
             % (cur["pixel"], got, target))
    t = cur["truth"]
    v = submit(dt, {"stencil": t["stencil"], "kase": t["kase"]})
    got = inspector_pixel(dt)
    if not v["right"] or not got["visible"] or got["pixel"] != cur["pixel"] or \
            got["title"] != "pixel (%d, %d)" % tuple(cur["pixel"]):
        fail("after a solve the inspector shows %s, not the exercise's pixel %s"
             % (got, cur["pixel"]))
    leave(dt, before)
    got = inspector_pixel(dt)
    if got["pixel"] is not None or (got["title"] or "").startswith("pixel ("):
        fail("after leaving the exercise the inspector still shows %s (the exercise's pixel was "
             "%s)" % (got, cur["pixel"]))
    print("inspector: pinned %s before, shows the exercise's pixel %s at open and after the "
          "solve, and no pixel after leaving (%r)" % (target, cur["pixel"], got["title"]))


def check_refused_and_leave(dt):
    before = dt.evaluate("recodePage.signature()")
    cur = start(dt, "a-spans-b")
    t = cur["truth"]
    v = submit(dt, {"stencil": broken(t["stencil"], 1), "kase": t["kase"]})
    if v["right"] or not v["verdict"]:
        fail("a wrong pass 2 gave no refusal: %r" % v)
    # Values the browser's own validation refuses: no verdict at all, not the old one.
    v = submit(dt, {"stencil": [16, -1, 4.5, 1, 1], "kase": t["kase"]})
    left = dt.evaluate("document.getElementById('predict-feedback').textContent")
    if v["verdict"] is not None or left.strip():
        fail("after an answer the browser refused, the feedback still says %r" % left)
    leave(dt, before)
    # A pose change closes an open exercise, and the page says so; the student's pose stays.
    for eid in ("b-spans-a", "own-pixel"):
        cur = None if eid == "own-pixel" else start(dt, eid)
        if eid == "own-pixel":
            dt.evaluate("recodePredict.start('own-pixel'); 0")
            px = dt.evaluate("(function () { const d = recodePage.rayData; const w = d.crop[2] -"
                             " d.crop[0]; for (let i = 0; i < d['case'].length; ++i) if"
                             " (d['case'][i] >= 0) return [d.crop[0] + i % w, d.crop[1] +"
                             " Math.floor(i / w)]; return null; })()")
            click_pixel(dt, "#silhouettes canvas[data-region]", *px)
            if not dt.evaluate("!!recodePredict.current()"):
                fail("own pixel: the click chose no pixel")
        updates = dt.evaluate("recodePage.metrics.updates")
        dt.evaluate("(function () { const i = document.getElementById('pos-B-x');"
                    " i.value = String(Number(i.value) + 0.05);"
                    " i.dispatchEvent(new Event('change')); })()")
        settle(dt, updates)
        s = dt.evaluate("({open: !!recodePredict.current(), note: (document.getElementById("
                        "'predict-note') || {}).textContent || ''})")
        if s["open"] or "closed" not in s["note"] or "pose changed" not in s["note"]:
            fail("%s: a pose change left %s" % (eid, s))
    print("a refused answer clears the verdict; leaving restores the pose; a pose change that "
          "closes an exercise says so (exercise and own pixel)")
    updates = dt.evaluate("recodePage.metrics.updates")
    dt.evaluate("recodePage.load(%s); 0" % json.dumps({"axis": "x", "resolution": 256,
                                                       "mor": "min", "boxTest": True}))
    settle(dt, updates)


LAYOUT_JS = """
(function () {
  const ins = document.getElementById('inspector').getBoundingClientRect();
  const over = [];
  const sel = '#live-top, #live-summary, #predict, #live-result section, #live-result > p, #terms, h1';
  document.querySelectorAll(sel).forEach(function (n) {
    const r = n.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) return;
    const w = Math.min(r.right, ins.right) - Math.max(r.left, ins.left);
    const h = Math.min(r.bottom, ins.bottom) - Math.max(r.top, ins.top);
    if (w > 0 && h > 0) over.push((n.id || n.tagName) + ' ' + Math.round(w) + 'x' + Math.round(h));
  });
  const result = document.getElementById('live-result').getBoundingClientRect();
  return {over: over, position: getComputedStyle(document.getElementById('inspector')).position,
          belowPictures: ins.top >= result.bottom - 1, width: document.documentElement.clientWidth,
          scrollWidth: document.documentElement.scrollWidth};
})()
"""


def check_layout(dt):
    report = []
    for width in (800, 1400):
        dt.call("Emulation.setDeviceMetricsOverride", width=width, height=900,
                deviceScaleFactor=1, mobile=False)
        dt.evaluate("window.scrollTo(0, 0); 0")
        seen = []
        # The whole page, a screen at a time: a fixed panel stays put while the page scrolls.
        height = dt.evaluate("document.documentElement.scrollHeight")
        for y in range(0, height, 600):
            dt.evaluate("window.scrollTo(0, %d); 0" % y)
            r = dt.evaluate(LAYOUT_JS)
            if r["over"]:
                fail("at %d px wide (scrolled to %d) the inspector covers %s"
                     % (width, y, r["over"]))
            seen.append(r)
        r = seen[0]
        if width == 800 and (r["position"] == "fixed" or not r["belowPictures"]):
            fail("at 800 px the inspector is %s, not docked below the pictures" % r["position"])
        report.append("%d px: inspector %s, nothing covered" % (width, r["position"]))
    dt.call("Emulation.clearDeviceMetricsOverride")
    print("layout: " + "; ".join(report))


def check_scale(dt):
    ticks = dt.evaluate("recodePage.view3d.lookFromSide(); recodePage.view3d.scale()")
    scene = dt.evaluate("recodePage.scene3d")
    k = {"x": 0, "y": 1, "z": 2}[scene["axis"]]
    if len(ticks) < 4:
        fail("the 3-D view's depth scale has %d ticks" % len(ticks))
    for t in ticks:
        if abs(t["world"][k] - t["value"]) > 1e-9:
            fail("a depth-scale tick labelled %s lies at %s" % (t["value"], t["world"]))
    lo, hi = scene["depth_range"]
    if ticks[0]["value"] > lo + 1e-9 + (hi - lo) / 4 or ticks[-1]["value"] < hi - (hi - lo) / 4:
        fail("the depth scale %s..%s does not span the blocks' range %s"
             % (ticks[0]["value"], ticks[-1]["value"], scene["depth_range"]))
    along = dt.evaluate("recodePage.view3d.lookAlongAxis(); recodePage.view3d.scale().length")
    if along:
        fail("looking along the axis the depth scale still labels %d ticks on one point" % along)
    print("depth scale: %d ticks from %s %s to %s, each at its coordinate"
          % (len(ticks), scene["axis"], ticks[0]["value"], ticks[-1]["value"]))


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    recode, work = sys.argv[1], os.path.abspath(sys.argv[2])
    chromium = chromium_and_fresh_workdir(work, "the interactive page's lessons")
    if chromium is None:
        return 77
    index_html = write_page(recode, os.path.join(work, "page"))
    size = os.path.getsize(index_html)
    # Not even the page's source (its scripts' comments included) names a file of the repo.
    with open(index_html, encoding="utf-8") as f:
        named = sorted(set(re.findall(r"[\w./-]*(?:docs/|\.md\b)[\w./-]*", f.read())))
    if named:
        fail("the page's source names files outside it: %s" % named[:5])
    if size >= MAX_PAGE_BYTES:
        fail("the page is %d bytes, over its budget of %d" % (size, MAX_PAGE_BYTES))
    profile = tempfile.mkdtemp(prefix="recode-chromium-")
    proc, ws_url = start_chromium(chromium, profile)
    try:
        dt = DevTools(ws_url)
        open_page(dt, index_html)
        check_terms(dt)
        page_refs(dt, "the page as loaded")
        names = dt.evaluate("Array.from(document.querySelectorAll('figcaption')).map(function"
                            " (f) { return f.textContent; }).join(' | ')")
        check_scale(dt)
        redraw = drag_timing(dt)
        check_layout(dt)
        check_inspector(dt)
        check_refused_and_leave(dt)
        tol = dt.evaluate("recodePredict.tolerance")
        exercises = dt.evaluate("recodePredict.exercises")
        geometry = [e for e in exercises if e.get("ask")]
        asked = set()
        for e in exercises:
            # A picture an exercise names (in quotes) is one the page shows.
            for quoted in e["intro"].split("\u201c")[1:]:
                name = quoted.split("\u201d")[0]
                if name not in names:
                    fail("exercise %s names the picture %r; the page's pictures are %s"
                         % (e["id"], name, names[:300]))
        for e in geometry:
            check_geometry_exercise(recode, work, dt, e, tol)
            form = dt.evaluate("document.getElementById('predict-form').textContent")
            if ("within %s" % tol) not in form and ("depths" in e["ask"] or
                                                    "ranges" in e["ask"]):
                fail("exercise %s does not state its tolerance %s: %r" % (e["id"], tol, form))
            page_refs(dt, "exercise " + e["id"])
            asked.update(e["ask"])
        if asked != {"depths", "ranges", "mor", "boxtest", "passes"}:
            fail("the geometry exercises ask only %s" % sorted(asked))
        touch = [e for e in geometry if e["pick"].get("touching") and "depths" in e["ask"]]
        if not touch:
            fail("no geometry exercise has the blocks touching along a face")
        # Every exercise's own text and feedback: anchors only, no file.
        for e in exercises:
            if e["pick"].get("own") or e.get("ask"):
                continue
            cur = start(dt, e["id"])
            t = cur["truth"]
            submit(dt, {"stencil": broken(t["stencil"], 4), "kase": t["kase"]})
            page_refs(dt, "exercise " + e["id"] + " with its feedback")
        if dt.problems():
            fail("console errors: " + "; ".join(dt.problems()))
    finally:
        proc.kill()
        shutil.rmtree(profile, ignore_errors=True)
    print("redraw after a drag at 256 px: %.1f ms; page %d bytes" % (redraw, size))
    print("interactive lessons OK: %d geometry exercises, terms, anchors, inspector and layout"
          % len(geometry))
    return 0


if __name__ == "__main__":
    sys.exit(main())
