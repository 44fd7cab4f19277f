#!/usr/bin/python3
"""Checks the teaching parts of `recode explain --interactive`'s page in headless Chromium.

The 3-D view (page/scene3d.js): looking along the view axis with one block shown, its canvas is
not blank and every block pixel of the reference's silhouettes picture (the CPU device's
coverage, as the page shows it) is drawn at the view's projection of the pixel's centre, and
every pixel it leaves empty is empty there, up to one pixel at an edge; a ray pinned in the
inspector is drawn through the pixel's centre, entering and leaving each block at the depths
the inspector reports, and those points lie on the blocks' triangles (a ray cast in Python).

The exercises that give the depths (page/predict.js; those on the geometry are
check_interactive_lessons.py's): each chooses a pixel whose case is the one it was written for;
its answers equal the native `recode pair --pixel` on the exported scene; the right answers are
accepted; answers with one pass's value taken from a wrong pass (or its bit flipped) are refused
naming that pass, whose section is shown once asked for; a wrong case names the read-back. Together
the exercises cover cases 1-8, a pixel outside the MOR and a pixel where the blocks only touch;
the student's progress survives a reload. The page loads and runs with no console error, stays
under 3 MB, and the time of a redraw after a drag is reported (measured, not judged).

Usage: check_interactive_teaching.py RECODE WORKDIR
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

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "apps"))
sys.path.insert(0, HERE)
from check_explain_browser import (  # noqa: E402
    DevTools, chromium_and_fresh_workdir, fail, start_chromium)
from check_interactive_browser import open_page, settle, write_page  # noqa: E402

TIMEOUT_S = 60
MAX_PAGE_BYTES = 3 * 1024 * 1024
DEPTH_ONE = 16777215
PERM = {"x": (1, 2, 0), "y": (2, 0, 1), "z": (0, 1, 2)}  # world index of (u, v, d)
PASS_IDS = ["set_z", "test_z", "load_amin", "test_amin_front", "test_amin_back"]
PASS_BITS = [1, 1, 1, 4, 8]  # what a broken rule flips when no other pass's value differs


def world(axis, u, v, d):
    p = [0.0, 0.0, 0.0]
    k = PERM[axis]
    p[k[0]], p[k[1]], p[k[2]] = u, v, d
    return p


def pixel_centre(scene, x, y):
    umin, vmin, umax, vmax = scene["window"]
    w, h = scene["resolution"]
    return umin + (x + 0.5) * (umax - umin) / w, vmin + (y + 0.5) * (vmax - vmin) / h


SECOND_POSE = {"axis": "y", "resolution": 128, "mor": "min", "blocks": [
    {"name": "A", "shape": "ellipsoid", "sizes": {"radii": [1, 0.6, 0.4]},
     "position": [0, 0, 0], "rotation": [20, 30, 10], "obj": None},
    {"name": "B", "shape": "capped_cone", "sizes": {"radius0": 0.6, "radius1": 0.3, "height": 2},
     "position": [0.3, 0.5, 0.2], "rotation": [40, -10, 25], "obj": None}]}

# --- the 3-D view ---------------------------------------------------------------------------------

PICTURE_JS = """
(function () {
  const c = document.querySelector('#silhouettes canvas[data-region]');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  return {region: c.dataset.region.split(',').map(Number), width: c.width, height: c.height,
          rgb: Array.from(d).filter(function (v, i) { return i % 4 !== 3; })};
})()
"""


def silhouettes(dt):
    """The reference's coverage as the page's silhouettes picture shows it: {(x, y): bits}."""
    p = dt.evaluate(PICTURE_JS)
    colours = {(17, 17, 17): 0, (58, 120, 216): 1, (214, 69, 69): 2, (155, 64, 192): 3}
    r = p["region"]
    if p["width"] != r[2] - r[0] or p["height"] != r[3] - r[1]:
        fail("the silhouettes picture is %dx%d for the region %s" % (p["width"], p["height"], r))
    cover, other = {}, 0
    rgb = p["rgb"]
    for row in range(p["height"]):
        for col in range(p["width"]):
            k = 3 * (row * p["width"] + col)
            c = colours.get(tuple(rgb[k:k + 3]))
            if c is None:
                other += 1  # the MOR's outline drawn over the picture: no coverage to read
                continue
            cover[(r[0] + col, r[3] - 1 - row)] = c
    return cover, other


def view_pixels(dt):
    p = dt.evaluate("(function () { const p = recodePage.view3d.readPixels(); let s = '';"
                    " for (let i = 0; i < p.data.length; i += 4)"
                    " s += (p.data[i] === 17 && p.data[i + 1] === 17 && p.data[i + 2] === 17)"
                    " ? '0' : '1'; return {w: p.width, h: p.height, s: s}; })()")
    return p["w"], p["h"], p["s"]


def check_silhouettes(dt, scene):
    """Each block alone, looked at along the axis, against the reference's coverage."""
    cover, other = silhouettes(dt)
    dmid = sum(scene["depth_range"]) / 2
    dt.evaluate("recodePage.view3d.lookAlongAxis(); 0")
    points = []
    for (x, y) in sorted(cover):
        u, v = pixel_centre(scene, x, y)
        points.append(world(scene["axis"], u, v, dmid))
    projected = dt.evaluate("(%s).map(function (p) { return recodePage.view3d.project(p); })"
                            % json.dumps(points))
    # Along the axis the window fills the canvas: its corners at the canvas's corners.
    umin, vmin, umax, vmax = scene["window"]
    corners = dt.evaluate("[%s, %s].map(function (p) { return recodePage.view3d.project(p); })"
                          % (json.dumps(world(scene["axis"], umin, vmin, dmid)),
                             json.dumps(world(scene["axis"], umax, vmax, dmid))))
    size = dt.evaluate("[document.getElementById('view3d').width,"
                       " document.getElementById('view3d').height]")
    want = [[0, size[1]], [size[0], 0]]
    if any(abs(corners[i][k] - want[i][k]) > 1e-6 for i in range(2) for k in range(2)):
        fail("along the axis the window's corners are drawn at %s, not %s" % (corners, want))
    report = []
    for bit, name in ((1, "A"), (2, "B")):
        dt.evaluate("recodePage.view3d.lookAlongAxis(); recodePage.view3d.setVisible({A: %s, B: %s,"
                    " axes: false, window: false, mor: false, ray: false}); 0"
                    % ("true" if bit == 1 else "false", "true" if bit == 2 else "false"))
        w, h, drawn = view_pixels(dt)
        if "1" not in drawn:
            fail("the 3-D view draws nothing for block %s" % name)
        shown = {}
        for (xy, (px, py)) in zip(sorted(cover), projected):
            cx, cy = int(px), int(py)
            if not (0 <= cx < w and 0 <= cy < h):
                continue
            shown[xy] = drawn[cy * w + cx] == "1"
        exact = near = bad = 0
        bad_pixels = []
        for xy, there in shown.items():
            ref = (cover[xy] & bit) != 0
            if there == ref:
                exact += 1
                continue
            x, y = xy
            # Within a pixel: a neighbour of the reference's has what the view drew here.
            if any((cover.get((x + dx, y + dy), -1) & bit != 0) == there
                   for dx in (-1, 0, 1) for dy in (-1, 0, 1) if (x + dx, y + dy) in cover):
                near += 1
            else:
                bad += 1
                bad_pixels.append(xy)
        covered = sum(1 for c in cover.values() if c & bit)
        if covered == 0 or len(shown) < len(cover) // 2:
            fail("block %s: %d covered pixels, %d of %d pixels inside the view's canvas"
                 % (name, covered, len(shown), len(cover)))
        if bad:
            fail("block %s: %d pixels differ from the reference's coverage by more than a pixel,"
                 " e.g. %s" % (name, bad, bad_pixels[:5]))
        report.append("%s %d covered, %d exact, %d within a pixel" % (name, covered, exact, near))
    dt.evaluate("recodePage.view3d.setVisible({A: true, B: true, axes: true, window: true,"
                " mor: true, ray: true}); 0")
    print("3-D silhouettes along %s (%d pixels compared, %d under the MOR outline): %s"
          % (scene["axis"], len(cover), other, "; ".join(report)))


def click_pixel(dt, selector, x, y):
    """A mouse click at the centre of frame pixel (x, y) on the picture `selector` names (its
    data-region is the frame rectangle it shows, rows from the top)."""
    pos = dt.evaluate("(function () { const c = document.querySelector(%s);"
                      " c.scrollIntoView({block: 'center'});"
                      " const r = c.dataset.region.split(',').map(Number);"
                      " const b = c.getBoundingClientRect();"
                      " return {x: b.left + (%d - r[0] + 0.5) * b.width / (r[2] - r[0]),"
                      " y: b.top + (r[3] - 1 - %d + 0.5) * b.height / (r[3] - r[1])}; })()"
                      % (json.dumps(selector), x, y))
    for kind in ("mousePressed", "mouseReleased"):
        dt.call("Input.dispatchMouseEvent", type=kind, x=pos["x"], y=pos["y"], button="left",
                buttons=1 if kind == "mousePressed" else 0, clickCount=1)
    time.sleep(0.2)


def ray_hits(positions, triangles, origin, direction):
    """(t, triangle's corners) where origin + t * direction crosses the mesh's triangles
    (Moller-Trumbore, in doubles)."""
    hits = []
    for k in range(0, len(triangles), 3):
        p = [positions[3 * triangles[k + j]: 3 * triangles[k + j] + 3] for j in range(3)]
        e1 = [p[1][i] - p[0][i] for i in range(3)]
        e2 = [p[2][i] - p[0][i] for i in range(3)]
        q = [direction[1] * e2[2] - direction[2] * e2[1],
             direction[2] * e2[0] - direction[0] * e2[2],
             direction[0] * e2[1] - direction[1] * e2[0]]
        det = sum(e1[i] * q[i] for i in range(3))
        if abs(det) < 1e-15:
            continue
        s = [origin[i] - p[0][i] for i in range(3)]
        a = sum(s[i] * q[i] for i in range(3)) / det
        r = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]]
        b = sum(direction[i] * r[i] for i in range(3)) / det
        if a < -1e-9 or b < -1e-9 or a + b > 1 + 1e-9:
            continue
        hits.append((sum(e2[i] * r[i] for i in range(3)) / det, p))
    return hits


def snap_allowance(scene, corners):
    """How far, in depth steps, the reference's depth at a pixel may lie from the exact
    surface: its vertices are snapped to 1/256 pixel in x and y (at most 1/512 off, so the
    plane's depth moves by at most its slope times that, a convex combination of the corners'
    errors), and z is rounded to float and to 24 bits (a few steps)."""
    k = PERM[scene["axis"]]
    q = [[c[k[0]], c[k[1]], c[k[2]]] for c in corners]  # (u, v, d)
    e1 = [q[1][i] - q[0][i] for i in range(3)]
    e2 = [q[2][i] - q[0][i] for i in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
         e1[0] * e2[1] - e1[1] * e2[0]]
    umin, vmin, umax, vmax = scene["window"]
    w, h = scene["resolution"]
    dmin, dmax = scene["depth_range"]
    slope = (abs(n[0]) * (umax - umin) / w + abs(n[1]) * (vmax - vmin) / h) / 512 / abs(n[2])
    return slope / ((dmax - dmin) / DEPTH_ONE) + 4


def check_ray(dt, scene):
    """Pins an interfering pixel in the inspector by a click; the 3-D ray follows it."""
    d = dt.evaluate("(function () { const d = recodePage.rayData; const w = d.crop[2] - d.crop[0];"
                    " let best = null; for (let i = 0; i < d['case'].length; ++i) {"
                    " if (d['case'][i] >= 3 && d['case'][i] <= 6) { best = i; break; } }"
                    " return {i: best, x: d.crop[0] + best % w,"
                    " y: d.crop[1] + Math.floor(best / w),"
                    " a: [d.a_front[best], d.a_back[best]], b: [d.b_front[best], d.b_back[best]]};"
                    " })()")
    if d["i"] is None:
        fail("the loaded pose has no interfering pixel to inspect")
    x, y = d["x"], d["y"]
    # A click at the pixel on the first picture (the inspector pins it; the 3-D view follows).
    click_pixel(dt, "#live-result canvas[data-region]", x, y)
    title = dt.evaluate("document.getElementById('inspector-title').textContent")
    if title != "pixel (%d, %d)" % (x, y):
        fail("the click pinned %r, not pixel (%d, %d)" % (title, x, y))
    points = dt.evaluate("recodePage.view3d.rayPoints()")
    want = {("A", "enter"): d["a"][0], ("A", "exit"): d["a"][1], ("B", "enter"): d["b"][0],
            ("B", "exit"): d["b"][1]}
    got = {(p["block"], p["end"]): p for p in points}
    if set(got) != set(want):
        fail("the 3-D ray has the points %s, the inspector's pixel has %s"
             % (sorted(got), sorted(want)))
    dmin, dmax = scene["depth_range"]
    u, v = pixel_centre(scene, x, y)
    step = (dmax - dmin) / DEPTH_ONE
    worst = 0.0
    for key, z in want.items():
        p = got[key]
        if p["depth"] != z:
            fail("%s %s: the 3-D view's depth %d, the inspector's %d" % (key + (p["depth"], z)))
        expected = world(scene["axis"], u, v, dmax - z / DEPTH_ONE * (dmax - dmin))
        if p["world"] != expected:
            fail("%s %s: the 3-D point %s, the inspector's depth puts it at %s"
                 % (key + (p["world"], expected)))
        # Independent of both: where the pixel's ray crosses the block's triangles.
        block = scene["blocks"][0 if key[0] == "A" else 1]
        origin = world(scene["axis"], u, v, 0.0)
        direction = world(scene["axis"], 0.0, 0.0, 1.0)
        ts = ray_hits(block["positions"], block["triangles"], origin, direction)
        if len(ts) < 2:
            fail("the ray through (%d, %d) misses block %s's triangles in Python" % (x, y, key[0]))
        # The viewer is on +d: the block is entered at its largest d and left at its smallest.
        d_true, corners = max(ts) if key[1] == "enter" else min(ts)
        off = abs(expected[PERM[scene["axis"]][2]] - d_true) / step
        allowed = snap_allowance(scene, corners)
        worst = max(worst, off / allowed)
        if off > allowed:
            fail("%s %s: the 3-D point is %.1f depth steps from the block's surface (snapping "
                 "and rounding allow %.1f)" % (key + (off, allowed)))
    print("3-D ray at pixel (%d, %d): 4 points at the inspector's depths, on the triangles "
          "within %.0f%% of what snapping and rounding allow" % (x, y, 100 * worst))


# --- the exercises --------------------------------------------------------------------------------

def native_pixel(recode, work, dt, x, y):
    """The native `recode pair --pixel` on the page's exported scene and options."""
    st = dt.evaluate("({text: recodePage.sceneText(), mor: recodePage.state.mor,"
                     " boxTest: recodePage.state.boxTest})")
    path = os.path.join(work, "exercise-scene.json")
    with open(path, "w") as f:
        f.write(st["text"])
    cmd = [recode, "pair", path, "--mor", st["mor"], "--json", "--no-timing",
           "--pixel", "%d,%d" % (x, y)]
    if not st["boxTest"]:
        cmd.append("--no-box-test")
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(" ".join(cmd) + ": " + r.stderr.strip())
    p = json.loads(r.stdout)["pixel"]
    return [p["steps"][s]["stencil"] for s in PASS_IDS], (-1 if p["case"] is None else p["case"])


def answer(dt, stencil, kase):
    """Types the answers into the form and presses Check; returns the page's verdict."""
    js = ["(function () {"]
    for k, v in enumerate(stencil):
        js.append("document.getElementById('predict-stencil-%d').value = '%d';" % (k + 1, v))
    js.append("document.getElementById('predict-case').value = '%d';" % kase)
    js.append("document.getElementById('predict-check').click();")
    js.append("const v = document.getElementById('predict-verdict');"
              " const r = document.getElementById('predict-rule');"
              " return {verdict: v ? v.textContent : null, right: v ? v.className === 'right'"
              " : null, rule: r ? r.textContent : null,"
              " shown: Array.from(document.querySelectorAll('#live-result section.shown'))"
              ".filter(function (s) { return s.offsetParent !== null; }).map(function (s)"
              " { return s.id; })}; })()")
    return dt.evaluate(" ".join(js))


def broken(truth, k):
    """The answers with pass k's value taken from a wrong pass (the one before it, or after
    it), or with the pass's bit flipped where every other pass left the same value."""
    for other in (k - 1, k + 1):
        if 0 <= other < len(truth) and truth[other] != truth[k]:
            v = truth[other]
            break
    else:
        v = truth[k] ^ PASS_BITS[k] if k != 1 else (truth[k] & ~3) | ((truth[k] + 1) & 3)
    out = list(truth)
    out[k] = v
    return out


def check_exercise(recode, work, dt, e):
    updates = dt.evaluate("recodePage.metrics.updates")
    dt.evaluate("recodePredict.start(%s); 0" % json.dumps(e["id"]))
    settle(dt, updates)
    cur = dt.evaluate("(function () { const c = recodePredict.current(); return c && {pixel:"
                      " c.pixel, truth: c.truth, i: c.index}; })()")
    if not cur:
        fail("exercise %s: no pixel was chosen" % e["id"])
    x, y = cur["pixel"]
    truth, kase = cur["truth"]["stencil"], cur["truth"]["kase"]
    if kase != e["want"]:
        fail("exercise %s: its pixel (%d, %d) is case %d, the exercise is about case %d"
             % (e["id"], x, y, kase, e["want"]))
    hidden = dt.evaluate("(function () { const visible = function (n) {"
                         " return !!n && n.offsetParent !== null; };"
                         " const shown = ['inspector', 'case-counts', 'set_z', 'test_amin_back',"
                         " 'read_stencil', 'verdict'].filter(function (id) {"
                         " return visible(document.getElementById(id)); });"
                         " if (visible(document.querySelector('#live-result > p.verdict')))"
                         " shown.push('the verdict under the title');"
                         " return shown; })()")
    if hidden:
        fail("exercise %s: the answer is not hidden: %s visible" % (e["id"], hidden))
    n_stencil, n_case = native_pixel(recode, work, dt, x, y)
    if n_stencil != truth or n_case != kase:
        fail("exercise %s at (%d, %d): the page checks against %s case %d, recode pair --pixel "
             "says %s case %d" % (e["id"], x, y, truth, kase, n_stencil, n_case))
    refused = []
    for k in range(5):
        wrong = broken(truth, k)
        v = answer(dt, wrong, kase)
        title = dt.evaluate("recodePredict.passes[%d].title" % k)
        if v["right"] or title not in (v["verdict"] or ""):
            fail("exercise %s: pass %d answered %s (the reference: %s) gave %r, not a refusal "
                 "naming %s" % (e["id"], k + 1, wrong, truth, v["verdict"], title))
        if v["shown"]:
            fail("exercise %s: a wrong pass %d showed pictures before they were asked for: %s"
                 % (e["id"], k + 1, v["shown"]))
        shown = dt.evaluate("document.getElementById('predict-show-section').click();"
                            " Array.from(document.querySelectorAll('#live-result"
                            " section.shown')).filter(function (s) { return s.offsetParent"
                            " !== null; }).map(function (s) { return s.id; })")
        if shown != [PASS_IDS[k]]:
            fail("exercise %s: asking for a wrong pass %d's pictures showed %s"
                 % (e["id"], k + 1, shown))
        refused.append(k + 1)
    v = answer(dt, truth, (kase + 1) % 9 if kase >= 0 else 0)
    if v["right"] or "Read stencil" not in (v["verdict"] or ""):
        fail("exercise %s: a wrong case gave %r, not a refusal naming the read-back"
             % (e["id"], v["verdict"]))
    v = answer(dt, truth, kase)
    if not v["right"]:
        fail("exercise %s: the reference's answers %s case %d were refused: %r"
             % (e["id"], truth, kase, v["verdict"]))
    interval = dt.evaluate("(function () { const d = recodePage.rayData; const i = %d; return"
                           " {a: [d.a_front[i], d.a_back[i]], b: [d.b_front[i], d.b_back[i]],"
                           " cov: d.coverage[i], mor: d.mor}; })()" % cur["i"])
    print("exercise %-16s pixel (%2d, %2d) case %2d stencil %s = recode pair --pixel; right "
          "accepted, passes %s and the case refused by name" % (e["id"], x, y, kase, truth,
                                                               refused))
    return kase, (x, y), interval


def check_exercises(recode, work, dt):
    exercises = dt.evaluate("recodePredict.exercises.filter(function (e) { return !e.ask; })"
                            ".map(function (e) { return {id: e.id, want: e.want, pick: e.pick};"
                            " })")
    cases, touching, outside = set(), False, False
    for e in exercises:
        if e["pick"].get("own"):
            continue
        kase, (x, y), iv = check_exercise(recode, work, dt, e)
        cases.add(kase)
        m = iv["mor"]
        if kase == -1 and (iv["cov"] & 1) and not (m[0] <= x < m[2] and m[1] <= y < m[3]):
            outside = True
        if 3 <= kase <= 6 and (iv["a"][0] == iv["b"][1] or iv["a"][1] == iv["b"][0]):
            touching = True
    missing = set(range(1, 9)) - cases
    if missing or not outside or not touching:
        fail("the exercises miss cases %s, a pixel outside the MOR (%s) or a touching pixel (%s)"
             % (sorted(missing), outside, touching))
    # The own-pixel exercise: a click on the picture "Coverage of A and B" chooses the pixel.
    dt.evaluate("recodePredict.start('own-pixel'); 0")
    target = dt.evaluate("(function () { const d = recodePage.rayData; const w = d.crop[2] -"
                         " d.crop[0]; for (let i = 0; i < d['case'].length; ++i) if (d['case'][i]"
                         " >= 0) return [d.crop[0] + i % w, d.crop[1] + Math.floor(i / w)];"
                         " return null; })()")
    click_pixel(dt, "#silhouettes canvas[data-region]", *target)
    cur = dt.evaluate("(function () { const c = recodePredict.current(); return c && {pixel:"
                      " c.pixel, truth: c.truth}; })()")
    if not cur or cur["pixel"] != target:
        fail("own pixel: clicking (%d, %d) chose %s" % (target[0], target[1], cur))
    n_stencil, n_case = native_pixel(recode, work, dt, *target)
    if [n_stencil, n_case] != [cur["truth"]["stencil"], cur["truth"]["kase"]]:
        fail("own pixel: the page's answers %s differ from recode pair --pixel's %s"
             % (cur["truth"], [n_stencil, n_case]))
    if not answer(dt, n_stencil, n_case)["right"]:
        fail("own pixel: the right answers were refused")
    print("the exercises cover cases 1-8, a pixel outside the MOR and a touching pixel; "
          "own pixel (%d, %d) chosen by a click" % tuple(target))
    return len(exercises)


def drag_timing(dt):
    """Updates after a drag on a picture (the module, the pictures and the 3-D view) in the
    page's own clock: the median of 7."""
    box = dt.evaluate("(function () { const c = document.querySelector('#live-result canvas');"
                      " c.scrollIntoView({block: 'center'}); const b = c.getBoundingClientRect();"
                      " return {x: b.left + b.width / 2, y: b.top + b.height / 2}; })()")
    updates, after_drag = dt.evaluate("recodePage.metrics.updates"), []
    for k in range(7):
        x, y = box["x"], box["y"]
        step = 4 if k % 2 == 0 else -4
        dt.call("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left",
                buttons=1, clickCount=1)
        dt.call("Input.dispatchMouseEvent", type="mouseMoved", x=x + step, y=y, button="left",
                buttons=1)
        dt.call("Input.dispatchMouseEvent", type="mouseReleased", x=x + step, y=y, button="left",
                buttons=0, clickCount=1)
        updates = settle(dt, updates)
        after_drag.append(dt.evaluate("recodePage.metrics.lastMs"))
    return statistics.median(after_drag)


def timing(dt):
    """A redraw after a drag at the page's 256 pixels and at its largest, 512, and a turn of
    the 3-D view alone (median of 7)."""
    at256 = drag_timing(dt)
    updates = dt.evaluate("recodePage.metrics.updates")
    dt.evaluate("(function () { const s = document.getElementById('resolution'); s.value = '512';"
                " s.dispatchEvent(new Event('change')); })()")
    settle(dt, updates)
    at512 = drag_timing(dt)
    turns = []
    for k in range(7):
        dt.evaluate("recodePage.view3d.turn(%d, 3); 0" % (5 if k % 2 == 0 else -5))
        turns.append(dt.evaluate("recodePage.view3d.lastDrawMs"))
    return at256, at512, statistics.median(turns)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    recode, work = sys.argv[1], os.path.abspath(sys.argv[2])
    chromium = chromium_and_fresh_workdir(work, "the interactive page's 3-D view and exercises")
    if chromium is None:
        return 77
    index_html = write_page(recode, os.path.join(work, "page"))
    size = os.path.getsize(index_html)
    if size >= MAX_PAGE_BYTES:
        fail("the page is %d bytes, over its budget of %d" % (size, MAX_PAGE_BYTES))
    profile = tempfile.mkdtemp(prefix="recode-chromium-")
    proc, ws_url = start_chromium(chromium, profile)
    try:
        dt = DevTools(ws_url)
        open_page(dt, index_html)
        if not dt.evaluate("!!recodePage.view3d"):
            fail("the page has no 3-D view: " + dt.evaluate(
                "document.getElementById('view3d-note').textContent"))
        scene = dt.evaluate("recodePage.scene3d")
        check_silhouettes(dt, scene)
        check_ray(dt, scene)
        dt.evaluate("recodePage.view3d.turn(35, 20); 0")
        dt.screenshot(os.path.join(work, "view3d.png"))
        drag256, drag512, turn_ms = timing(dt)
        # A second pose: other shapes, turned about every axis, seen along y at 128 pixels.
        updates = dt.evaluate("recodePage.metrics.updates")
        dt.evaluate("recodePage.load(%s); 0" % json.dumps(SECOND_POSE))
        settle(dt, updates)
        check_silhouettes(dt, dt.evaluate("recodePage.scene3d"))
        count = check_exercises(recode, work, dt)
        dt.screenshot(os.path.join(work, "exercise.png"))
        # Progress is kept by the browser: a reload lists every exercise as solved.
        dt.call("Page.reload")
        time.sleep(1.0)
        deadline = time.time() + TIMEOUT_S
        while not dt.evaluate("!!(window.recodePredict && document.getElementById("
                              "'predict-progress'))"):
            if time.time() > deadline:
                fail("the page did not come back after a reload")
            time.sleep(0.1)
        shown = dt.evaluate("document.getElementById('predict-progress').textContent")
        total = dt.evaluate("recodePredict.exercises.length")
        if not shown.startswith("%d of %d solved" % (count, total)):
            fail("after a reload the page says %r, not the %d solved here of %d"
                 % (shown, count, total))
        if dt.problems():
            fail("console errors: " + "; ".join(dt.problems()))
    finally:
        proc.kill()
        shutil.rmtree(profile, ignore_errors=True)
    print("redraw after a drag (median of 7, in the page): %.1f ms at 256 px, %.1f ms at 512 px; "
          "a turn of the 3-D view alone: %.1f ms; page %d bytes"
          % (drag256, drag512, turn_ms, size))
    print("interactive teaching OK: 3-D view and %d exercises, screenshots in %s" % (count, work))
    return 0


if __name__ == "__main__":
    sys.exit(main())
