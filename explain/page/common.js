// What the explain pages' scripts share (inspector.js, interactive.js, scene3d.js, predict.js):
// HTML escaping, rectangles, the ray data's crop index and encodings (coverage and stencil
// bits, cases), the blocks' colours, the view axes and the reading of the steps' names, rules
// and operands from the ray data. Loaded before the other scripts.
window.recodeCommon = (function () {
  'use strict';

  function esc(t) {
    return String(t).replace(/[&<>"]/g, function (ch) {
      return {'&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;'}[ch];
    });
  }

  // Pixel (x, y) in the half-open rectangle r = [x0, y0, x1, y1]; false when there is none.
  function inRect(r, x, y) { return !!r && x >= r[0] && x < r[2] && y >= r[1] && y < r[3]; }

  // Where pixel (x, y) is in the ray data's per-pixel arrays (rows of the crop, bottom row
  // first), or -1 outside the crop, where the page has no values.
  function cropIndex(data, x, y) {
    const c = data && data.crop;
    return c && inRect(c, x, y) ? (y - c[1]) * (c[2] - c[0]) + (x - c[0]) : -1;
  }

  // The blocks' colours (RGB 0-255) in the pictures and the 3-D view.
  const COLOURS = {A: [58, 120, 216], B: [214, 69, 69]};

  // The image plane (u, v) of each view axis, and the world component of (u, v, d): cyclic
  // permutations, so (u, v, d) is right-handed like (x, y, z). The viewer is on the +d side.
  const AXES = ['x', 'y', 'z'];
  const PLANE = {x: ['y', 'z'], y: ['z', 'x'], z: ['x', 'y']};
  const PERM = {x: [1, 2, 0], y: [2, 0, 1], z: [0, 1, 2]};

  // The ray data's encodings, named once for every script. coverage: bit COVER_A where A
  // covers the pixel, COVER_B where B does. case: one of CASES (0-8), NOT_EXAMINED (-1) outside
  // the MOR; INTERFERING the cases whose two depth intervals share a depth (the blocks collide
  // iff some pixel is in one). A depth is an integer from 0 (nearest) to the ray data's
  // depth_max (farthest).
  const COVER_A = 1, COVER_B = 2;
  const CASES = [0, 1, 2, 3, 4, 5, 6, 7, 8];
  const NOT_EXAMINED = -1;
  const INTERFERING = [3, 4, 5, 6];
  // The stencil: the count in bits 0-1 (COUNT_BITS), bit 2 (FRONT_BIT, value 4) and bit 3
  // (BACK_BIT, value 8), which passes 4 and 5 write.
  const COUNT_BITS = 3, FRONT_BIT = 4, BACK_BIT = 8;
  function covers(coverage, bit) { return (coverage & bit) !== 0; }
  function countOf(stencil) { return stencil & COUNT_BITS; }
  function interferes(kase) { return INTERFERING.indexOf(kase) >= 0; }

  // The steps' names, rules and operands (what decides the stencil each leaves besides the
  // stencil before it: face depths named as the ray data's arrays, "a_covers"), stated once in
  // the C++ that writes the sections and sent with the ray data ("step_words"): the five passes
  // a student predicts, the read-back, and every step's name by its id ("set_z": "1 SetZ").
  const PASS_IDS = ['set_z', 'test_z', 'load_amin', 'test_amin_front', 'test_amin_back'];
  function stepWords(data) {
    const byId = {};
    ((data && data.step_words) || []).forEach(function (w) {
      byId[w.id] = {id: w.id, title: w.name, rule: w.rule, operands: w.operands || []};
    });
    const names = {};
    Object.keys(byId).forEach(function (id) { names[id] = byId[id].title; });
    return {passes: PASS_IDS.map(function (id) { return byId[id]; }),
      readBack: byId.read_stencil, names: names};
  }

  return {esc: esc, inRect: inRect, cropIndex: cropIndex, COLOURS: COLOURS, AXES: AXES,
    PLANE: PLANE, PERM: PERM, COVER_A: COVER_A, COVER_B: COVER_B, CASES: CASES,
    NOT_EXAMINED: NOT_EXAMINED, INTERFERING: INTERFERING, FRONT_BIT: FRONT_BIT,
    BACK_BIT: BACK_BIT, covers: covers, countOf: countOf, interferes: interferes,
    stepWords: stepWords};
})();
