// What the explain pages' scripts share (inspector.js, interactive.js, scene3d.js, predict.js):
// HTML escaping, rectangles, the ray data's crop index, the blocks' colours, the view axes and
// the passes' titles and rules, each stated here once. Loaded before the other scripts.
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

  // The steps of the pair algorithm as the page names them, and the rule each applies to one
  // pixel (the five passes a student predicts, then the read-back). The glossary on the page,
  // the exercises and the ray inspector all show these.
  const PASSES = [
    {id: 'set_z', title: '1 SetZ', rule: 'depth cleared to 0 and stencil to 0 over the MOR; ' +
      'every fragment of A passes GEQUAL and REPLACEs the stencil with 1. So: 1 where A ' +
      'covers the pixel, 0 where it does not (or outside the MOR: the scissor keeps every ' +
      'pass away and the stencil stays 0). The depth buffer ends holding Amax.'},
    {id: 'test_z', title: '2 TestZ', rule: 'only where A is present (stencil test 1 \u2264 ' +
      'count), each face of B at or in front of Amax (LEQUAL) INCRements the count in bits ' +
      '0-1. So the count becomes 1 + the number of B\u2019s two boundaries at or before ' +
      'Amax; where A is absent nothing changes.'},
    {id: 'load_amin', title: '3 Load Amin', rule: 'A is drawn again into depth cleared to 1, ' +
      'leaving Amin in the depth buffer; the stencil write mask is 0, so the stencil does not ' +
      'change at all.'},
    {id: 'test_amin_front', title: '4 B front vs Amin', rule: 'only B\u2019s front face is ' +
      'drawn. Where A is present it INVERTs bit 2 (value 4) when that face is at or behind ' +
      'Amin (GEQUAL); where A is absent the stencil test fails and sfail INVERTs bit 2 anyway, ' +
      'so bit 2 then says that B covers the pixel. No face of B: nothing changes.'},
    {id: 'test_amin_back', title: '5 B back vs Amin', rule: 'the same for B\u2019s back face ' +
      'and bit 3 (value 8): INVERT when it is at or behind Amin where A is present, always ' +
      'where A is absent and B covers the pixel.'},
  ];
  const READ_BACK = {id: 'read_stencil', title: '6 Read stencil', rule: 'the read-back ' +
    'decodes the stencil (see \u201cstencil encoding\u201d in the terms): count 0 gives case 0 ' +
    'without bits 2-3, else 8; count 1 gives 1 without them, else 2; count 2 gives 3 with both ' +
    'bits, else 4; count 3 gives 5 with both, 6 with one, 7 with neither. A pixel outside the ' +
    'MOR is not read back: not examined.'};
  const STEP_TITLES = {contact_near: '7 Contact near', contact_far: '8 Contact far'};
  PASSES.concat([READ_BACK]).forEach(function (p) { STEP_TITLES[p.id] = p.title; });

  return {esc: esc, inRect: inRect, cropIndex: cropIndex, COLOURS: COLOURS, AXES: AXES,
    PLANE: PLANE, PERM: PERM, PASSES: PASSES, READ_BACK: READ_BACK, STEP_TITLES: STEP_TITLES};
})();
