// The interactive page's exercises ("predict" mode). Each poses two blocks, chooses a pixel (or
// the student clicks one on the picture "Coverage of A and B") and hides every buffer. The
// student answers, in order, what the exercise asks: where the pixel's ray enters and leaves
// each block (read off the 3-D view's depth scale and the blocks' numbers, no depths given),
// or the blocks' ranges along the view axis; which MOR modes examine the pixel; whether the
// box test stops the pair; the stencil after each of the five passes and the case the
// read-back decodes. Each answer is checked against the reference's own values (the ray data
// the WebAssembly module recorded, its MOR in each mode, its box test), step by step in that
// order (STEPS); a wrong one names the first step misapplied, says that step's rule and the
// student's inputs to it, and shows that pass's pictures only when asked. Progress stays in
// this browser (localStorage), never sent anywhere. Every term the exercises use links to its
// definition in the page's Terms.
window.recodePredict = (function () {
  'use strict';
  const page = window.recodePage;
  const common = window.recodeCommon;
  const esc = common.esc, inRect = common.inRect, covers = common.covers;
  const $ = function (id) { return document.getElementById(id); };
  const STORE = 'recode.predict.v1';
  const NOT_EXAMINED = common.NOT_EXAMINED;  // the "case" of a pixel outside the MOR
  // The five passes and the read-back with their names, rules and operands, from the ray data
  // (the C++ that writes the sections states them); set by the first update, before any
  // exercise opens.
  let PASSES = [], DECODE = null;
  const MODES = ['min', 'max', 'full'];
  const BLOCKS = ['A', 'B'];
  // How far a depth the student reads may lie from the reference's (world units along the
  // view axis): the exercises' faces lie on round values, far more than this apart.
  const TOLERANCE = 0.01;
  // The face depths a step's operands name (the ray data's arrays): the block, which end of it
  // the student gives, and the name the rules use.
  const FACES = {
    a_front: {block: 'A', end: 'near', label: 'A<sub>min</sub>'},
    a_back: {block: 'A', end: 'far', label: 'A<sub>max</sub>'},
    b_front: {block: 'B', end: 'near', label: 'B<sub>min</sub>'},
    b_back: {block: 'B', end: 'far', label: 'B<sub>max</sub>'},
  };
  // The two questions on a block's near and far ends: the field names and their words.
  const ENDS = {
    depths: {field: 'depth', title: 'the depths of ', noun: 'Depths', what: 'depth',
      term: 'term-entry-exit'},
    ranges: {field: 'range', title: 'the range of ', noun: 'Range', what: 'range',
      term: 'term-bounding-box'},
  };

  function term(id, text) { return '<a href="#' + id + '">' + text + '</a>'; }

  // Every answer field's id, minted here only: the form's builders, render and readAnswers all
  // call it. fieldId('depth', 'A', 'near') is 'predict-depth-A-near'; fieldId('stencil', 3),
  // fieldId('bits', 3), fieldId('mor', 'max'), fieldId('box'), fieldId('case').
  function fieldId(what, block, end) {
    return ['predict', what, block, end].filter(function (p) {
      return p !== undefined;
    }).join('-');
  }

  // Boxes seen along z (the viewer on +z: a larger z is nearer); A is 2 deep unless said
  // otherwise. Every exercise names the case its pixel must have, so a change to the reference
  // that moved it would be caught by the page's test, not taught wrong. `ask`: what the student
  // answers, in this order (default: the passes alone, with the depths given).
  const box = function (name, size, position) {
    return {name: name, shape: 'box', sizes: {size: size}, position: position,
      rotation: [0, 0, 0], obj: null};
  };
  const A2 = box('A', [2, 2, 2], [0, 0, 0]);
  const EXERCISES = [
    {id: 'a-only', title: 'A alone on the ray', want: 1, pick: {kase: 1}, mor: 'max',
      blocks: [box('A', [3, 3, 2], [0, 0, 0]), box('B', [1, 1, 1], [0, 0, 0])],
      intro: 'A is wider than B and the ' + term('term-mor-max', 'MOR is max') + ', so the ' +
        'passes also run on the ring of A around B. Only A is on this ray.',
      terms: ['term-mor-max', 'term-passes', 'term-cases']},
    {id: 'b-only', title: 'B alone on the ray', want: 8, pick: {kase: 8}, mor: 'max',
      blocks: [box('A', [1, 1, 1], [0, 0, 0]), box('B', [3, 3, 2], [0, 0, 0])],
      intro: 'Now B is the wide one: only B is on this ray. Where A is absent, the stencil ' +
        'test of passes 2, 4 and 5 fails; what does each pass do on a failed test?',
      terms: ['term-stencil', 'term-depth-test', 'term-passes', 'term-stencil-encoding']},
    {id: 'mor-min', title: 'Outside the MOR', want: NOT_EXAMINED, pick: {outsideMor: true},
      mor: 'min', blocks: [box('A', [3, 3, 2], [0, 0, 0]), box('B', [1, 1, 1], [0, 0, 0])],
      intro: 'The first pair again, with the ' + term('term-mor-min', 'MOR min') + ': where ' +
        'the footprints of the two blocks\u2019 ' + term('term-bounding-box', 'bounding boxes') +
        ' overlap. This pixel is covered by A but lies outside that rectangle.',
      terms: ['term-mor', 'term-mor-min', 'term-scissor']},
    {id: 'a-spans-b', title: 'A spans B', want: 5, pick: {kase: 5}, mor: 'min',
      blocks: [A2, box('B', [1, 1, 1], [0.3, 0.2, 0])],
      intro: 'Both blocks on the ray, B wholly inside A\u2019s depth.',
      terms: ['term-entry-exit', 'term-passes', 'term-stencil-encoding', 'term-cases']},
    {id: 'b-spans-a', title: 'B spans A', want: 4, pick: {kase: 4}, mor: 'min',
      blocks: [A2, box('B', [1, 1, 4], [0.3, 0.2, 0])],
      intro: 'B reaches through all of A, in front of it and behind it.',
      terms: ['term-entry-exit', 'term-passes', 'term-stencil-encoding', 'term-cases']},
    {id: 'near-end-inside', title: 'B\u2019s near end inside A', want: 3, pick: {kase: 3},
      mor: 'min', blocks: [A2, box('B', [1, 1, 2], [0.3, 0.2, -1])],
      intro: 'B starts inside A and leaves through A\u2019s far side.',
      terms: ['term-entry-exit', 'term-passes', 'term-stencil-encoding', 'term-cases']},
    {id: 'far-end-inside', title: 'B\u2019s far end inside A', want: 6, pick: {kase: 6},
      mor: 'min', blocks: [A2, box('B', [1, 1, 2], [0.3, 0.2, 1])],
      intro: 'B starts in front of A and ends inside it.',
      terms: ['term-entry-exit', 'term-passes', 'term-stencil-encoding', 'term-cases']},
    {id: 'b-behind', title: 'B behind A', want: 2, pick: {kase: 2}, mor: 'min', boxTest: false,
      blocks: [box('A', [2, 2, 1], [0, 0, 0]), box('B', [1, 1, 1], [0.3, 0.2, -2])],
      intro: 'B lies wholly behind A. The ' + term('term-box-test', 'box test') + ' would stop ' +
        'before any pass (the ranges along z do not meet); it is off here so that the passes ' +
        'run.', terms: ['term-box-test', 'term-passes', 'term-cases']},
    {id: 'b-in-front', title: 'B in front of A', want: 7, pick: {kase: 7}, mor: 'min',
      boxTest: false,
      blocks: [box('A', [2, 2, 1], [0, 0, 0]), box('B', [1, 1, 1], [0.3, 0.2, 2])],
      intro: 'B lies wholly in front of A, the ' + term('term-box-test', 'box test') +
        ' off again.', terms: ['term-box-test', 'term-passes', 'term-cases']},
    {id: 'touching', title: 'Touching', want: 6, pick: {touching: true}, mor: 'min',
      blocks: [A2, box('B', [1, 1, 2], [0.3, 0.2, 2])],
      intro: 'B\u2019s back face lies exactly on A\u2019s front face: the two intervals share ' +
        'one depth. Do the comparisons count equal depths?',
      terms: ['term-depth-test', 'term-interfering', 'term-cases']},
    {id: 'own-pixel', title: 'Your own pixel', want: null, pick: {own: true}, mor: null,
      blocks: null,
      intro: 'Any pose: shape and move the blocks first (or keep this one), then click a ' +
        'pixel on the picture \u201cCoverage of A and B\u201d below.',
      terms: ['term-pixel', 'term-passes', 'term-cases']},
    // The geometry: no depths given, the student reads them off the blocks.
    {id: 'read-depths', title: 'Read the depths, then the passes', want: 3, pick: {kase: 3},
      mor: 'min', ask: ['depths', 'passes'],
      blocks: [box('A', [2, 2, 1.5], [0, 0, 0.25]), box('B', [1, 1, 1], [0.3, 0.2, -0.75])],
      intro: 'No depths this time: from the blocks\u2019 sizes and positions (a box of size ' +
        '(sx, sy, sz) at (x, y, z) spans z \u2212 sz/2 to z + sz/2) and the 3-D view\u2019s ' +
        'depth scale, say where the pixel\u2019s ray enters and leaves each block, then predict ' +
        'the passes.', terms: ['term-entry-exit', 'term-depth', 'term-view-axis', 'term-passes',
        'term-cases']},
    {id: 'face-touch', title: 'Touching along a face', want: 6, pick: {touching: true},
      mor: 'min', ask: ['depths', 'boxtest', 'passes'],
      blocks: [A2, box('B', [1, 1, 1], [0.3, 0.2, 1.5])],
      intro: 'B sits on A: B\u2019s bottom face lies in A\u2019s top face. Read the depths, ' +
        'decide whether the box test lets the passes run, then predict them.',
      terms: ['term-entry-exit', 'term-box-test', 'term-depth-test', 'term-interfering']},
    {id: 'box-gap', title: 'The box test: apart along the axis', want: null, pick: {none: true},
      mor: 'min', ask: ['ranges', 'boxtest'],
      blocks: [box('A', [2, 2, 1], [0, 0, 0]), box('B', [1, 1, 1], [0.3, 0.2, -2])],
      intro: 'Seen along z the two blocks overlap, but are they near each other in z? Give ' +
        'each block\u2019s range along z and say whether any pass runs.',
      terms: ['term-bounding-box', 'term-box-test', 'term-view-axis']},
    {id: 'mor-modes', title: 'Which MOR examines it? (max)', want: NOT_EXAMINED,
      pick: {outsideMor: true}, mor: 'min', ask: ['mor', 'passes'],
      blocks: [box('A', [3, 3, 2], [0, 0, 0]), box('B', [1, 1, 1], [0.8, 0.8, 0])],
      intro: 'The pixel is on A, outside the MOR of mode min that this page runs. Which of the ' +
        'three modes examine it? Then the passes, in mode min.',
      terms: ['term-mor', 'term-mor-min', 'term-mor-max', 'term-mor-full']},
    {id: 'mor-full', title: 'Which MOR examines it? (full)', want: 0, pick: {outsideMax: true},
      mor: 'full', ask: ['mor', 'passes'],
      blocks: [box('A', [1.5, 1.5, 2], [0, 0, 0]), box('B', [1, 1, 1], [0.5, 0.4, 0])],
      intro: 'This pixel is on neither block. Which modes examine it? Then the passes, in the ' +
        'mode this page runs now, full.',
      terms: ['term-mor', 'term-mor-min', 'term-mor-max', 'term-mor-full', 'term-cases']},
  ];

  // The exercise's state, one of:
  //   {name: 'idle', note}: no exercise; `note` (HTML, may be '') says why the last one closed;
  //   {name: 'posing', exercise, saved}: the exercise's pose is loading, its first update
  //     chooses the pixel and opens it;
  //   {name: 'choosing', exercise, saved}: the own-pixel exercise waits for a click;
  //   {name: 'open', exercise, saved, pixel, index, truth, signature}: the question is on
  //     screen, about `pixel` ([x, y], or null) at crop index `index`; `truth` the reference's
  //     answers; `signature` the pose it was asked on.
  // `saved`: the pose the first exercise replaced, which leaving restores.
  let mode = {name: 'idle', note: ''};
  const progress = load();

  function load() {
    try {
      const p = JSON.parse(window.localStorage.getItem(STORE) || '{}');
      return {solved: p.solved || {}};
    } catch (e) {
      return {solved: {}};  // storage off or unreadable: progress for this visit only
    }
  }
  function save() {
    try { window.localStorage.setItem(STORE, JSON.stringify(progress)); } catch (e) { /* off */ }
  }
  function asks(e, what) { return (e.ask || ['passes']).indexOf(what) >= 0; }

  // --- choosing the pixel ---------------------------------------------------------------------

  // The pixel of the crop that satisfies `test`, nearest the middle of all that do (so that it
  // is well inside a region, not on its edge); null when none does.
  function pickWhere(rays, test) {
    const c = rays.crop, w = c[2] - c[0];
    const found = [];
    for (let i = 0; i < rays['case'].length; ++i) {
      const x = c[0] + (i % w), y = c[1] + Math.floor(i / w);
      if (test(i, x, y)) found.push([x, y, i]);
    }
    if (!found.length) return null;
    let sx = 0, sy = 0;
    found.forEach(function (p) { sx += p[0]; sy += p[1]; });
    sx /= found.length; sy /= found.length;
    let best = found[0], bestD = Infinity;
    found.forEach(function (p) {
      const d = (p[0] - sx) * (p[0] - sx) + (p[1] - sy) * (p[1] - sy);
      if (d < bestD) { best = p; bestD = d; }
    });
    return best;
  }

  function choosePixel(pick, rays) {
    if (pick.kase !== undefined)
      return pickWhere(rays, function (i) { return rays['case'][i] === pick.kase; });
    if (pick.outsideMor)
      return pickWhere(rays, function (i, x, y) {
        return covers(rays.coverage[i], common.COVER_A) && !inRect(rays.mor, x, y);
      });
    if (pick.outsideMax) {  // on no block, two pixels or more outside the MOR of mode max
      const m = page.morOf('max');
      const far = m && [m[0] - 2, m[1] - 2, m[2] + 2, m[3] + 2];
      return pickWhere(rays, function (i, x, y) {
        return rays.coverage[i] === 0 && !inRect(far, x, y);
      });
    }
    if (pick.touching)  // interfering, and one block's far end is the other's near end
      return pickWhere(rays, function (i) {
        return common.interferes(rays['case'][i]) && (rays.b_back[i] === rays.a_front[i] ||
                                                      rays.a_back[i] === rays.b_front[i]);
      });
    return null;
  }

  // A depth of the ray data (0 to depth_max) as the coordinate along the view axis (the 3-D
  // view's conversion).
  function worldDepth(rays, z) {
    const r = rays.depth_range;
    return r[1] - (z / rays.depth_max) * (r[1] - r[0]);
  }

  // The reference's answers: at crop index i (when there is a pixel) the ray's depths, the
  // stencil after each pass and the case; the blocks' ranges along the view axis (their own
  // vertices); whether each MOR mode examines the pixel; whether the box test stops the pair.
  function truthAt(e, rays, pixel) {
    const t = {};
    const i = pixel ? pixel[2] : -1;
    if (i >= 0) {
      const ids = rays.steps.map(function (s) { return s.id; });
      t.stencil = PASSES.map(function (p) {
        const k = ids.indexOf(p.id);
        return k < 0 ? 0 : rays.stencil[k][i];  // a pass that did not run left the clear, 0
      });
      t.kase = rays['case'][i];
      const ends = function (bit, front, back) {
        return covers(rays.coverage[i], bit)
          ? [worldDepth(rays, front[i]), worldDepth(rays, back[i])] : null;
      };
      t.depths = {A: ends(common.COVER_A, rays.a_front, rays.a_back),
        B: ends(common.COVER_B, rays.b_front, rays.b_back)};
      t.inMor = inRect(rays.mor, pixel[0], pixel[1]);
    }
    const s = page.scene3d, k = common.PERM[s.axis][2];
    t.ranges = {};
    s.blocks.forEach(function (b, n) {
      let lo = Infinity, hi = -Infinity;
      for (let v = k; v < b.positions.length; v += 3) {
        lo = Math.min(lo, b.positions[v]);
        hi = Math.max(hi, b.positions[v]);
      }
      t.ranges[BLOCKS[n]] = [hi, lo];  // near end first: the viewer is on +axis
    });
    if (asks(e, 'mor')) {
      t.mor = {};
      MODES.forEach(function (m) { t.mor[m] = inRect(page.morOf(m), pixel[0], pixel[1]); });
    }
    t.boxStops = page.pair.boxes_overlap === false;
    return t;
  }

  // --- checking an answer ----------------------------------------------------------------------

  function close(a, b) { return Math.abs(Number(a) - b) <= TOLERANCE; }

  // One block's depths (or range): [near, far] given against the reference's; what is wrong,
  // or '' when nothing is. `other`: the other block's, to name a depth taken from it.
  function depthError(name, given, truth, other, what) {
    if (truth === null)
      return given.none ? '' : name + ' is not on this ray: its footprint misses the pixel.';
    if (given.none) return name + ' is on this ray: its footprint covers the pixel.';
    const near = given.near, far = given.far;
    if (close(near, truth[0]) && close(far, truth[1])) return '';
    if (close(near, truth[1]) && close(far, truth[0]))
      return 'the near and far ends of ' + name + ' are swapped: the ray meets first the ' +
        'face nearer the viewer, at the larger coordinate along the view axis.';
    if (close(near, truth[1]))
      return 'the near end of ' + name + ' is taken from the wrong face: the face the ray ' +
        'leaves ' + name + ' through, not the one it enters through.';
    if (close(far, truth[0]))
      return 'the far end of ' + name + ' is taken from the wrong face: the face the ray ' +
        'enters ' + name + ' through, not the one it leaves through.';
    if (other && (close(near, other[0]) || close(near, other[1]) || close(far, other[0]) ||
                  close(far, other[1])))
      return 'a ' + what + ' of ' + name + ' is taken from the other block\u2019s faces.';
    return (close(near, truth[0]) ? 'the far end' : 'the near end') + ' of ' + name +
      ' is not where ' + (what === 'range' ? name + '\u2019s range ends' : 'the ray ' +
      (close(near, truth[0]) ? 'leaves' : 'enters') + ' ' + name) + ' (checked to within ' +
      TOLERANCE + ').';
  }

  // A refusal: `step` the question ('depths', 'ranges', 'mor', 'boxtest', 'pass'), the step
  // misapplied (its title and rule), what is wrong, the student's inputs to it (HTML); for a
  // pass, `pass` (1-5, 6 for the read-back) and `stepId`, the section whose pictures show it.
  function refusal(step, title, rule, message, inputs, pass, stepId) {
    return {correct: false, step: step, pass: pass || 0, title: title, rule: rule,
      message: message, inputs: inputs || '', stepId: stepId};
  }

  // Each block's near and far ends (ENDS: where the ray enters and leaves it, or its range
  // along the view axis), A then B.
  function checkEnds(what, answers, open) {
    const q = ENDS[what], t = open.truth;
    for (let n = 0; n < BLOCKS.length; ++n) {
      const name = BLOCKS[n], given = answers[what][name];
      const other = what === 'depths' ? t.depths[BLOCKS[1 - n]] : null;
      const err = depthError(name, given, t[what][name], other, q.what);
      if (!err) continue;
      const none = '(not on this ray)';
      return refusal(what, q.title + name, definition(q.term), q.noun + ' of ' + name + ': ' +
        err, 'you gave: near end ' + esc(given.none ? none : given.near) + ', far end ' +
        esc(given.none ? none : given.far));
    }
    return null;
  }

  // Which MOR modes examine the pixel, in the order min, max, full.
  function checkMor(answers, open) {
    const m = MODES.find(function (x) { return Boolean(answers.mor[x]) !== open.truth.mor[x]; });
    if (!m) return null;
    return refusal('mor', 'MOR ' + m, definition('term-mor-' + m), 'MOR ' + m + ': you said it ' +
      (answers.mor[m] ? 'examines' : 'does not examine') + ' this pixel; read its definition ' +
      'again (the modes before it are right).',
      'pixel (' + open.pixel[0] + ', ' + open.pixel[1] + ')');
  }

  // Whether the box test stops the pair, against the ranges the student gave.
  function checkBoxTest(answers, open) {
    if ((answers.box === 'stops') === open.truth.boxStops) return null;
    const r = asks(open.exercise, 'ranges') ? answers.ranges : answers.depths;
    return refusal('boxtest', 'the box test', definition('term-box-test'), 'Box test: ' +
      'misapplied: you said ' + (answers.box === 'stops' ? 'it stops the pair before any pass' :
      'the passes run') + '. Compare the two blocks\u2019 ranges along the view axis (touching ' +
      'counts as meeting) and their footprints.', BLOCKS.map(function (n) {
        return n + ' from ' + esc(r[n].near) + ' to ' + esc(r[n].far);
      }).join('; ') + ' (as you gave them)');
  }

  // The stencil after each pass, then the case read back.
  function checkPasses(answers, open) {
    const t = open.truth;
    const k = PASSES.findIndex(function (p, n) {
      return Number(answers.stencil[n]) !== t.stencil[n];
    });
    if (k >= 0)
      return refusal('pass', PASSES[k].title, PASSES[k].rule, 'Pass ' + PASSES[k].title +
        ': its rule was misapplied here (the passes before it are right).',
        passInputs(k, answers), k + 1, PASSES[k].id);
    if (Number(answers.kase) === t.kase) return null;
    return refusal('pass', DECODE.title, DECODE.rule, 'Pass ' + DECODE.title + ': the case ' +
      'was misread from the stencil (the passes before it are right).',
      passInputs(PASSES.length, answers), PASSES.length + 1, DECODE.id);
  }

  // The questions in the order the student answers them, each checked only where the exercise
  // asks it: the first that returns a refusal is the step misapplied (the ones before it are
  // right).
  const STEPS = [
    {ask: 'depths', check: function (a, open) { return checkEnds('depths', a, open); }},
    {ask: 'ranges', check: function (a, open) { return checkEnds('ranges', a, open); }},
    {ask: 'mor', check: checkMor},
    {ask: 'boxtest', check: checkBoxTest},
    {ask: 'passes', check: checkPasses},
  ];

  // answers = {depths: {A: {near, far, none}, B: ...}, ranges: {A: {near, far}, B: ...},
  // mor: {min, max, full}, box: 'stops' | 'runs', stencil: [five numbers], kase: number (-1:
  // not examined)}; only what the exercise asks is read. Returns the first step's refusal
  // (refusal() above), or {correct: true, message} and records the exercise solved.
  function check(answers) {
    if (mode.name !== 'open') throw new Error('no exercise is open');
    const open = mode, e = open.exercise;
    let v = null;
    STEPS.some(function (s) {
      v = asks(e, s.ask) ? s.check(answers, open) : null;
      return v !== null;
    });
    if (v) return v;
    progress.solved[e.id] = true;
    save();
    return {correct: true, step: '', pass: 0, title: '', rule: '', inputs: '',
      message: 'Right: every step agrees with the reference.'};
  }

  // The definition the page's Terms give for `id` (its <dd>), as text.
  function definition(id) {
    const dt = $(id);
    const dd = dt && dt.nextElementSibling;
    return dd ? dd.textContent.replace(/\s+/g, ' ').trim() : '';
  }

  function stencilText(v) {
    return v + ' (binary ' + v.toString(2).padStart(4, '0') + ', count ' + common.countOf(v) + ')';
  }

  // What pass k (0-4; 5: the read-back) tested at the pixel: whether the pixel is in the MOR,
  // the stencil before it, as the student answered the pass before (right, or the check would
  // have stopped there), and the step's operands (common.js's stepWords): the face depths it
  // compares, as the student gave them or as the exercise gave them, and whether A is on the
  // ray.
  function passInputs(k, answers) {
    const open = mode, t = open.truth;
    const step = k < PASSES.length ? PASSES[k] : DECODE;
    const studentDepths = asks(open.exercise, 'depths');
    const operand = function (name) {
      if (name === 'a_covers') return 'A ' + (t.depths.A ? 'on' : 'not on') + ' this ray';
      const f = FACES[name];
      if (!f) return esc(name);  // named by the C++ but unknown here: shown as it is named
      if (studentDepths) {
        const d = answers.depths[f.block];
        return f.label + ' ' + (d.none ? 'none (not on this ray)' : esc(d[f.end]));
      }
      if (!t.depths[f.block]) return f.label + ' none (not on this ray)';
      return f.label + ' ' + depthText(page.rayData, page.rayData[name][open.index]);
    };
    const parts = ['pixel ' + (t.inMor ? 'inside' : 'outside') + ' the MOR',
      'stencil before it: ' + (k === 0 ? 'the clear value 0' :
        stencilText(Number(answers.stencil[k - 1])))].concat(step.operands.map(operand));
    const compares = step.operands.some(function (o) { return FACES[o] !== undefined; });
    return parts.join('; ') + (studentDepths && compares ?
      ' (depths as coordinates along the view axis: the larger is nearer the viewer)' : '');
  }

  // --- the panel -------------------------------------------------------------------------------

  function depthText(rays, v) { return (v / rays.depth_max).toFixed(6) + ' (' + v + ')'; }

  function blockText(b) {
    const s = b.sizes.size;
    return '<b>' + esc(b.name) + '</b>: a ' + esc(b.shape) + (s ? ' of size (' + s.join(', ') +
      ')' : '') + ' at (' + b.position.join(', ') + '), turned (' + b.rotation.join(', ') +
      ') degrees';
  }

  function depthInputs(what) {
    const f = ENDS[what].field;
    const number = function (n, end) {
      return '<label>' + end + ' end <input type="number" step="any" required id="' +
        fieldId(f, n, end) + '"></label>';
    };
    let h = '<fieldset id="predict-' + what + '"><legend>' + (what === 'depths'
      ? 'Where the ray enters and leaves each block (' + term('term-entry-exit', 'entry and ' +
        'exit') + '), as the coordinate along the ' + term('term-view-axis', 'view axis') +
        ', to within ' + TOLERANCE
      : 'Each block\u2019s range along the ' + term('term-view-axis', 'view axis') + ' (its ' +
        term('term-bounding-box', 'bounding box') + '), to within ' + TOLERANCE) +
      '</legend><table id="predict-inputs">';
    BLOCKS.forEach(function (n) {
      h += '<tr><th>' + n + '</th><td>' + number(n, 'near') + '</td><td>' + number(n, 'far') +
        '</td>' + (what === 'depths' ? '<td><label><input type="checkbox" id="' +
        fieldId(f, n, 'none') + '"> not on this ray</label></td>' : '') + '</tr>';
    });
    return h + '</table></fieldset>';
  }

  // The pixel, and its ray's depths where the exercise gives them.
  function pixelText(e, rays, open) {
    const x = open.pixel[0], y = open.pixel[1], i = open.index;
    let h = '<p id="predict-pixel">' + term('term-pixel', 'Pixel') + ' (' + x + ', ' + y + ')';
    if (!asks(e, 'mor'))
      h += ', ' + (inRect(rays.mor, x, y) ? 'inside' : '<b>outside</b>') + ' the ' +
        term('term-mor', 'MOR') + ' [' + (rays.mor ? rays.mor.join(', ') : '') + ')';
    if (e.ask) return h + '.</p>';
    const line = function (name, bit, front, back) {
      return '<li><b>' + name + '</b>: ' + (covers(rays.coverage[i], bit) ? 'enters at depth ' +
        depthText(rays, front) + ', leaves at ' + depthText(rays, back) :
        'not on this ray') + '</li>';
    };
    return h + '. Its ray (' + term('term-depth', 'depth') + ' 0 nearest the viewer, 1 ' +
      'farthest; the 3-D view marks where it enters and leaves each block):</p><ul>' +
      line('A', common.COVER_A, rays.a_front[i], rays.a_back[i]) +
      line('B', common.COVER_B, rays.b_front[i], rays.b_back[i]) + '</ul>';
  }

  function passFields() {
    let h = '<table><tr><th>after pass</th><th>' + term('term-stencil', 'stencil') +
      ' (0-15)</th></tr>';
    PASSES.forEach(function (p, k) {
      h += '<tr><td>' + term('term-pass-' + (k + 1), esc(p.title)) + '</td><td><input ' +
        'type="number" min="0" max="15" step="1" id="' + fieldId('stencil', k + 1) +
        '" required> <span class="bits" id="' + fieldId('bits', k + 1) + '"></span></td></tr>';
    });
    h += '<tr><td>' + term('term-read-back', esc(DECODE.title)) + ': the case</td><td>' +
      '<select id="' + fieldId('case') + '" required><option value="">choose</option>';
    common.CASES.forEach(function (c) {
      h += '<option value="' + c + '">case ' + c + '</option>';
    });
    h += '<option value="' + NOT_EXAMINED + '">not examined (outside the MOR)</option></select>' +
      '</td></tr></table>';
    return h + '<details id="predict-rules"><summary>The rules of the passes and of the ' +
      'read-back</summary><ol>' + PASSES.concat([DECODE]).map(function (p, k) {
      return '<li><b>' + term(k < PASSES.length ? 'term-pass-' + (k + 1) : 'term-read-back',
        esc(p.title)) + '</b>: ' + esc(p.rule) + '</li>';
    }).join('') + '</ol><p>Depth tests compare 24-bit values; equal depths pass both LEQUAL ' +
      'and GEQUAL (' + term('term-depth-test', 'depth tests') + '). The stencil test 1 &le; ' +
      'count reads bits 0-1 only. The read-back’s decoding: ' +
      term('term-stencil-encoding', 'stencil encoding') + ', ' +
      term('term-cases', 'the nine cases') + '.</p></details>';
  }

  function question(e, rays, open) {
    let h = open.pixel ? pixelText(e, rays, open) : '';
    if (e.ask) {
      h += '<p id="predict-blocks">The blocks, seen along ' + esc(page.state.axis) +
        ' (the viewer on the side of larger ' + esc(page.state.axis) + '): ' +
        e.blocks.map(blockText).join('; ') + '. The 3-D view is turned to show the depth ' +
        'scale on the view axis (its ticks are ' + esc(page.state.axis) + ' values)' +
        (open.pixel ? ' and the pixel\u2019s ray (yellow)' : '') + '.</p>';
    }
    h += '<form id="predict-form">';
    if (asks(e, 'depths')) h += depthInputs('depths');
    if (asks(e, 'ranges')) h += depthInputs('ranges');
    if (asks(e, 'mor')) {
      h += '<fieldset id="predict-mor"><legend>Which ' + term('term-mor', 'MOR') + ' modes ' +
        'examine this pixel?</legend>' + MODES.map(function (m) {
          return '<label><input type="checkbox" id="' + fieldId('mor', m) + '"> ' +
            term('term-mor-' + m, 'MOR ' + m) + '</label> ';
        }).join('') + '</fieldset>';
    }
    if (asks(e, 'boxtest')) {
      h += '<fieldset id="predict-boxtest"><legend>The ' + term('term-box-test', 'box test') +
        '</legend><select id="' + fieldId('box') + '" required><option value="">choose' +
        '</option><option value="stops">stops the pair: no pass runs</option><option ' +
        'value="runs">lets the passes run</option></select></fieldset>';
    }
    if (asks(e, 'passes')) h += passFields();
    h += '<button type="submit" id="predict-check">Check</button> ' +
      '<button type="button" id="predict-close">Leave the exercise</button></form>' +
      '<div id="predict-feedback" aria-live="polite"></div>';
    return h;
  }

  function listHtml() {
    let h = '<ol id="predict-list">';
    EXERCISES.forEach(function (e) {
      const done = progress.solved[e.id];
      h += '<li><button type="button" data-exercise="' + e.id + '">' + esc(e.title) +
        '</button>' + (done ? ' <span class="solved">\u2713 solved</span>' : '') + '</li>';
    });
    const n = EXERCISES.filter(function (e) { return progress.solved[e.id]; }).length;
    return h + '</ol><p id="predict-progress">' + n + ' of ' + EXERCISES.length +
      ' solved (kept in this browser only).</p>';
  }

  function practises(e) {
    return '<p class="practises">Practises ' + e.terms.map(function (id) {
      const dt = $(id);
      return term(id, dt ? esc(dt.textContent.replace(/\s+/g, ' ').trim()) : id);
    }).join(', ') + ' (under Terms below), and the page\u2019s sections once answered.</p>';
  }

  function render() {
    const panel = $('predict');
    let h = '<h2>Predict</h2><p>Each exercise poses the blocks and chooses a pixel; the ' +
      'buffers are hidden until you answer. Answer what it asks (the depths, the MOR, the box ' +
      'test, the stencil after each pass and the case), then check.</p>' +
      (mode.note ? '<p class="note" id="predict-note">' + mode.note + '</p>' : '') +
      '<div id="predict-list-wrap">' + listHtml() + '</div>';
    if (mode.exercise && mode.name !== 'posing') {
      const e = mode.exercise;
      h += '<div id="predict-exercise"><h3>' + esc(e.title) + '</h3><p>' + e.intro + '</p>' +
        practises(e) + (mode.name === 'open' ? question(e, page.rayData, mode) : '') + '</div>';
    }
    panel.innerHTML = h;
    bindList();
    if (mode.name === 'open') bindForm();
  }

  function bindForm() {
    PASSES.forEach(function (p, k) {
      const input = $(fieldId('stencil', k + 1));
      if (!input) return;
      input.addEventListener('input', function () {
        const v = Number(input.value);
        $(fieldId('bits', k + 1)).textContent =
          input.value !== '' && v >= 0 && v <= 15 ? 'binary ' + v.toString(2).padStart(4, '0') : '';
      });
    });
    BLOCKS.forEach(function (n) {  // "not on this ray": no depths to give
      const none = $(fieldId('depth', n, 'none'));
      if (!none) return;
      none.addEventListener('change', function () {
        ['near', 'far'].forEach(function (end) {
          const input = $(fieldId('depth', n, end));
          input.disabled = none.checked;
          input.required = !none.checked;
        });
      });
    });
    const form = $('predict-form');
    // An answer the browser refuses (out of range, not a whole number, missing) is no answer:
    // the verdict of the one before must not stay on screen as if it were this one's.
    form.addEventListener('invalid', clearFeedback, true);
    form.addEventListener('submit', function (ev) {
      ev.preventDefault();
      clearFeedback();
      showVerdict(check(readAnswers()));
    });
    $('predict-close').addEventListener('click', leave);
  }

  // The form's answers as check() takes them, each field read by its fieldId.
  function readAnswers() {
    const value = function (id) { const n = $(id); return n ? n.value : ''; };
    const ticked = function (id) { const n = $(id); return !!(n && n.checked); };
    const ends = function (what, n) {
      const f = ENDS[what].field;
      return {near: value(fieldId(f, n, 'near')), far: value(fieldId(f, n, 'far')),
        none: ticked(fieldId(f, n, 'none'))};
    };
    const kase = value(fieldId('case'));
    const a = {depths: {}, ranges: {}, mor: {}, box: value(fieldId('box')),
      stencil: PASSES.map(function (p, k) { return value(fieldId('stencil', k + 1)); }),
      kase: kase === '' ? NaN : Number(kase)};
    BLOCKS.forEach(function (n) {
      a.depths[n] = ends('depths', n);
      a.ranges[n] = ends('ranges', n);
    });
    MODES.forEach(function (m) { a.mor[m] = ticked(fieldId('mor', m)); });
    return a;
  }

  function bindList() {
    $('predict').querySelectorAll('[data-exercise]').forEach(function (b) {
      b.addEventListener('click', function () { start(b.dataset.exercise); });
    });
  }

  function hideSections() {
    document.querySelectorAll('#live-result section.shown').forEach(function (s) {
      s.classList.remove('shown');
    });
  }

  function clearFeedback() {
    hideSections();
    const f = $('predict-feedback');
    if (f) f.innerHTML = '';
  }

  // A wrong answer names the step, its rule and the student's inputs to it; a pass's section
  // (its pictures mark the pixel) is shown only when the student asks. A right one shows every
  // section again and the ray inspector at the exercise's pixel.
  function showVerdict(v) {
    hideSections();
    let h = '<p class="' + (v.correct ? 'right' : 'wrong') + '" id="predict-verdict">' +
      esc(v.message) + '</p>';
    if (!v.correct) {
      h += '<p id="predict-rule"><b>The rule of ' + esc(v.title) + ':</b> ' + esc(v.rule) +
        '</p><p id="predict-inputs-used"><b>What it tested, as you answered:</b> ' + v.inputs +
        '</p>';
      if (v.stepId && document.getElementById(v.stepId)) {
        h += '<p><button type="button" id="predict-show-section" data-step="' + v.stepId +
          '">Show the pictures of ' + esc(v.title) + '</button> (they show the answer at this ' +
          'pixel); or try again.</p>';
      } else {
        h += '<p>Try again.</p>';
      }
    } else {
      document.body.classList.remove('predicting');
      const p = mode.pixel;
      if (p) {
        page.showRay([p[0], p[1]]);
        window.recodeInspector.showPixel([p[0], p[1]]);
      }
      h += '<p>The buffers are shown again' + (p ? '; the ray inspector has pixel (' + p[0] +
        ', ' + p[1] + ')\u2019s whole story, the 3-D view its entry and exit points' : '') +
        '.</p>';
      $('predict-list-wrap').innerHTML = listHtml();
      bindList();
    }
    $('predict-feedback').innerHTML = h;
    const show = $('predict-show-section');
    if (show) {
      show.addEventListener('click', function () {
        const s = document.getElementById(show.dataset.step);
        if (s) {
          s.classList.add('shown');
          s.scrollIntoView({block: 'nearest'});
        }
      });
    }
  }

  // --- opening and leaving an exercise ------------------------------------------------------

  // idle, posing, choosing or open -> posing (choosing for the own-pixel exercise).
  function start(id) {
    const e = EXERCISES.find(function (x) { return x.id === id; });
    if (!e) throw new Error('no exercise ' + id);
    const saved = mode.name === 'idle' ? page.pose() : mode.saved;
    hideSections();
    document.body.classList.add('predicting');
    mode = {name: e.pick.own ? 'choosing' : 'posing', exercise: e, saved: saved};
    if (!e.pick.own)
      page.load({blocks: e.blocks, axis: 'z', resolution: 64, mor: e.mor,
        boxTest: e.boxTest !== false});
    render();
  }

  // posing or choosing -> open, at `pixel` ([x, y, crop index], or null).
  function open(pixel, rays) {
    const e = mode.exercise;
    mode = {name: 'open', exercise: e, saved: mode.saved,
      pixel: pixel ? [pixel[0], pixel[1]] : null, index: pixel ? pixel[2] : -1,
      truth: truthAt(e, rays, pixel), signature: page.signature()};
    // The inspector (hidden until the answer) and the 3-D ray are about this pixel, whatever
    // was pinned before; where the student reads the depths, the ray has no entry and exit
    // marks and the view is turned to show the depth scale.
    window.recodeInspector.showPixel(mode.pixel);
    page.showRay(mode.pixel, !asks(e, 'depths'));
    if (page.view3d && (asks(e, 'depths') || asks(e, 'ranges'))) page.view3d.lookFromSide();
    render();
  }

  // Any -> idle: the page shows the buffers again and the inspector no pixel; `restore` puts
  // back the pose the first exercise replaced; `note` (HTML) says why the exercise closed.
  function finish(restore, note) {
    const saved = mode.saved;
    mode = {name: 'idle', note: note || ''};
    document.body.classList.remove('predicting');
    hideSections();
    window.recodeInspector.showPixel(null);
    page.showRay(null);
    if (restore && saved) page.load(saved);
    render();
  }

  function leave() { finish(true); }

  // After every update of the page: an exercise whose pose just ran gets its pixel; one whose
  // pose the student changed is closed, and the page says so (its answer would no longer be
  // this pose's); the student's pose stays.
  page.onUpdate.push(function (rays) {
    if (!DECODE) {
      const words = common.stepWords(rays);
      PASSES = words.passes;
      DECODE = words.readBack;
      fillTerms();
    }
    if (mode.name === 'posing') {
      const e = mode.exercise;
      const p = e.pick.none ? null : choosePixel(e.pick, rays);
      if (p || e.pick.none) {
        open(p, rays);
      } else {
        finish(false, 'The exercise \u201c' + esc(e.title) + '\u201d has no pixel on its pose ' +
          '(the reference no longer gives it): please report it.');
      }
      return;
    }
    if (mode.name === 'open' && mode.signature !== page.signature()) {
      finish(false, 'The exercise \u201c' + esc(mode.exercise.title) + '\u201d was closed: the ' +
        'pose changed, and its answers belong to its own pose. Open it again to go back to ' +
        'that pose.');
    }
  });

  // The own-pixel exercise: a click on the picture "Coverage of A and B" (the only one shown)
  // picks it.
  document.addEventListener('click', function (ev) {
    if (mode.name !== 'choosing') return;
    const img = ev.target.closest && ev.target.closest('#live-result [data-region]');
    if (!img) return;
    const rays = page.rayData;
    const r = img.dataset.region.split(',').map(Number);
    const b = img.getBoundingClientRect();
    const x = r[0] + Math.floor((ev.clientX - b.left) / b.width * (r[2] - r[0]));
    const y = r[3] - 1 - Math.floor((ev.clientY - b.top) / b.height * (r[3] - r[1]));
    if (!rays.steps.length) {
      $('predict-exercise').insertAdjacentHTML('beforeend', '<p class="wrong">No pass ran on ' +
        'this pose (the ' + term('term-box-test', 'box test') + ' found the blocks apart): ' +
        'move them together, or switch the box test off, and click again.</p>');
      return;
    }
    const i = page.rayIndex(x, y);
    if (i < 0) {
      $('predict-exercise').insertAdjacentHTML('beforeend', '<p class="wrong">No ray data at (' +
        x + ', ' + y + '): choose a pixel in [' + rays.crop.join(', ') + ') (the MOR and a ' +
        'margin).</p>');
      return;
    }
    open([x, y, i], rays);
  }, true);

  // The passes' entries in the page's Terms, from the ray data.
  function fillTerms() {
    const list = $('terms-passes');
    if (!list) return;
    list.innerHTML = PASSES.concat([DECODE]).map(function (p, k) {
      return '<dt id="' + (k < PASSES.length ? 'term-pass-' + (k + 1) : 'term-read-back') +
        '">' + esc(p.title) + '</dt><dd>' + esc(p.rule) + '</dd>';
    }).join('');
  }

  render();
  return {
    get passes() { return PASSES; }, get decode() { return DECODE; },
    exercises: EXERCISES, tolerance: TOLERANCE, start: start,
    close: leave, check: check, current: function () { return mode.name === 'open' ? mode : null; },
    mode: function () { return mode.name; },
    progress: function () { return progress; }, choosePixel: choosePixel,
  };
})();
