// The interactive page's exercises ("predict" mode): the page poses two blocks, chooses a pixel
// (or the student clicks one on the silhouettes), shows where the pixel's ray enters and leaves
// each block, and hides every buffer. The student predicts the stencil after each of the five
// passes and the case the read-back decodes; each answer is checked against the reference's own
// buffers (the ray data the WebAssembly module recorded), and a wrong one names the first pass
// whose rule was misapplied, says that rule, and shows that pass's section. Progress stays in
// this browser (localStorage), never sent anywhere. docs/algorithm.md, section 12, lists the
// exercises with the sections each one practises.
window.recodePredict = (function () {
  'use strict';
  const page = window.recodePage;
  const $ = function (id) { return document.getElementById(id); };
  const STORE = 'recode.predict.v1';
  const NOT_EXAMINED = -1;  // the "case" of a pixel outside the MOR: never read back

  // The five passes a student predicts, in order, with the rule each one applies to one pixel
  // (docs/algorithm.md, section 3) and the stencil bits it may write.
  const PASSES = [
    {id: 'set_z', title: '1 SetZ', rule: 'depth cleared to 0 and stencil to 0 over the MOR; ' +
      'every fragment of A passes GEQUAL and REPLACEs the stencil with 1. So: 1 where A ' +
      'covers the pixel, 0 where it does not (or outside the MOR: the scissor keeps every ' +
      'pass away and the stencil stays 0).'},
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
  const DECODE = {title: '6 Read stencil', rule: 'the read-back decodes the stencil (section ' +
    '"Stencil encoding"): count 0 gives case 0 without bits 2-3, else 8; count 1 gives 1 ' +
    'without them, else 2; count 2 gives 3 with both bits, else 4; count 3 gives 5 with both, ' +
    '6 with one, 7 with neither. A pixel outside the MOR is not read back: not examined.'};

  // Boxes seen along z (the viewer on +z: a larger z is nearer); A is 2 deep unless said
  // otherwise. Every exercise names the case its pixel must have, so a change to the reference
  // that moved it would be caught by the page's test, not taught wrong.
  const box = function (name, size, position) {
    return {name: name, shape: 'box', sizes: {size: size}, position: position,
      rotation: [0, 0, 0], obj: null};
  };
  const A2 = box('A', [2, 2, 2], [0, 0, 0]);
  const EXERCISES = [
    {id: 'a-only', title: 'A alone on the ray', want: 1, pick: {kase: 1}, mor: 'max',
      blocks: [box('A', [3, 3, 2], [0, 0, 0]), box('B', [1, 1, 1], [0, 0, 0])],
      intro: 'A is wider than B and the MOR is <b>max</b>, so the passes also run on the ring ' +
        'of A around B. Only A is on this ray.', sections: [1, 2, 3, 4]},
    {id: 'b-only', title: 'B alone on the ray', want: 8, pick: {kase: 8}, mor: 'max',
      blocks: [box('A', [1, 1, 1], [0, 0, 0]), box('B', [3, 3, 2], [0, 0, 0])],
      intro: 'Now B is the wide one: only B is on this ray. Where A is absent, the stencil ' +
        'test of passes 2, 4 and 5 fails; what does each pass do on a failed test?',
      sections: [1, 3, 4]},
    {id: 'mor-min', title: 'Outside the MOR', want: NOT_EXAMINED, pick: {outsideMor: true},
      mor: 'min', blocks: [box('A', [3, 3, 2], [0, 0, 0]), box('B', [1, 1, 1], [0, 0, 0])],
      intro: 'The first pair again, with the MOR <b>min</b>: the overlap of the two blocks\u2019 ' +
        'footprints. This pixel is covered by A but lies outside that rectangle.',
      sections: [2, 3]},
    {id: 'a-spans-b', title: 'A spans B', want: 5, pick: {kase: 5}, mor: 'min',
      blocks: [A2, box('B', [1, 1, 1], [0.3, 0.2, 0])],
      intro: 'Both blocks on the ray, B wholly inside A\u2019s depth.', sections: [1, 3, 4]},
    {id: 'b-spans-a', title: 'B spans A', want: 4, pick: {kase: 4}, mor: 'min',
      blocks: [A2, box('B', [1, 1, 4], [0.3, 0.2, 0])],
      intro: 'B reaches through all of A, in front of it and behind it.', sections: [1, 3, 4]},
    {id: 'near-end-inside', title: 'B\u2019s near end inside A', want: 3, pick: {kase: 3},
      mor: 'min', blocks: [A2, box('B', [1, 1, 2], [0.3, 0.2, -1])],
      intro: 'B starts inside A and leaves through A\u2019s far side.', sections: [1, 3, 4]},
    {id: 'far-end-inside', title: 'B\u2019s far end inside A', want: 6, pick: {kase: 6},
      mor: 'min', blocks: [A2, box('B', [1, 1, 2], [0.3, 0.2, 1])],
      intro: 'B starts in front of A and ends inside it.', sections: [1, 3, 4]},
    {id: 'b-behind', title: 'B behind A', want: 2, pick: {kase: 2}, mor: 'min', boxTest: false,
      blocks: [box('A', [2, 2, 1], [0, 0, 0]), box('B', [1, 1, 1], [0.3, 0.2, -2])],
      intro: 'B lies wholly behind A. The box test would stop before any pass (the depth ranges ' +
        'do not meet); it is off here so that the passes run.', sections: [1, 2, 3, 4]},
    {id: 'b-in-front', title: 'B in front of A', want: 7, pick: {kase: 7}, mor: 'min',
      boxTest: false,
      blocks: [box('A', [2, 2, 1], [0, 0, 0]), box('B', [1, 1, 1], [0.3, 0.2, 2])],
      intro: 'B lies wholly in front of A, the box test off again.', sections: [1, 2, 3, 4]},
    {id: 'touching', title: 'Touching', want: 6, pick: {touching: true}, mor: 'min',
      blocks: [A2, box('B', [1, 1, 2], [0.3, 0.2, 2])],
      intro: 'B\u2019s back face lies exactly on A\u2019s front face: the two intervals share ' +
        'one depth. Do the comparisons count equal depths?', sections: [1, 3, 4]},
    {id: 'own-pixel', title: 'Your own pixel', want: null, pick: {own: true}, mor: null,
      blocks: null,
      intro: 'Any pose: shape and move the blocks first (or keep this one), then click a ' +
        'pixel on the silhouettes picture below.', sections: [1, 3, 4]},
  ];

  // docs/algorithm.md's sections an exercise practises (its table in section 12).
  const SECTIONS = {1: 'the nine cases', 2: 'the box test and the MOR', 3: 'the passes',
    4: 'the stencil encoding'};

  let current = null;    // {exercise, pixel, index, truth, signature}
  let pending = null;    // the exercise whose pose the page is running
  let choosing = false;  // the own-pixel exercise waits for a click
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

  function esc(t) {
    return String(t).replace(/[&<>"]/g, function (ch) {
      return {'&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;'}[ch];
    });
  }
  function inRect(r, x, y) { return r && x >= r[0] && x < r[2] && y >= r[1] && y < r[3]; }

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
        return (rays.coverage[i] & 1) !== 0 && !inRect(rays.mor, x, y);
      });
    if (pick.touching)  // interfering, and one block's far end is the other's near end
      return pickWhere(rays, function (i) {
        const k = rays['case'][i];
        return k >= 3 && k <= 6 && (rays.b_back[i] === rays.a_front[i] ||
                                    rays.a_back[i] === rays.b_front[i]);
      });
    return null;
  }

  // The reference's answers at crop index i: the stencil after each pass and the case.
  function truthAt(rays, i) {
    const ids = rays.steps.map(function (s) { return s.id; });
    const stencil = PASSES.map(function (p) {
      const k = ids.indexOf(p.id);
      return k < 0 ? 0 : rays.stencil[k][i];  // a pass that did not run left the clear, 0
    });
    return {stencil: stencil, kase: rays['case'][i]};
  }

  // --- checking an answer ----------------------------------------------------------------------

  // answers = {stencil: [five numbers], kase: number (-1: not examined)}. The first pass whose
  // value differs from the reference's is the one whose rule was misapplied: the values before
  // it were right, so the rule, applied to them, gives the reference's value. Returns
  // {correct, pass (1-5, 6 for the read-back), title, rule, message}.
  function check(answers) {
    if (!current) throw new Error('no exercise is open');
    const t = current.truth;
    let verdict = {correct: true, pass: 0, title: '', rule: ''};
    for (let k = 0; k < PASSES.length; ++k) {
      if (Number(answers.stencil[k]) !== t.stencil[k]) {
        verdict = {correct: false, pass: k + 1, title: PASSES[k].title, rule: PASSES[k].rule,
          stepId: PASSES[k].id};
        break;
      }
    }
    if (verdict.correct && Number(answers.kase) !== t.kase)
      verdict = {correct: false, pass: 6, title: DECODE.title, rule: DECODE.rule,
        stepId: 'read_stencil'};
    if (verdict.correct) {
      progress.solved[current.exercise.id] = true;
      save();
    }
    verdict.message = verdict.correct
      ? 'Right: every pass and the case agree with the reference.'
      : 'Pass ' + verdict.title + ': its rule was misapplied here (the passes before it are ' +
        'right).';
    return verdict;
  }

  // --- the panel -------------------------------------------------------------------------------

  function depthText(rays, v) { return (v / rays.depth_max).toFixed(6) + ' (' + v + ')'; }

  function question(rays, i, x, y) {
    const cov = rays.coverage[i];
    const line = function (name, has, front, back) {
      return '<li><b>' + name + '</b>: ' + (has ? 'enters at depth ' + depthText(rays, front) +
        ', leaves at ' + depthText(rays, back) : 'not on this ray') + '</li>';
    };
    let h = '<p id="predict-pixel">Pixel (' + x + ', ' + y + '), ' +
      (inRect(rays.mor, x, y) ? 'inside' : '<b>outside</b>') + ' the MOR [' +
      (rays.mor ? rays.mor.join(', ') : '') + '). Its ray (depth 0 nearest the viewer, 1 ' +
      'farthest; the 3-D view marks where it enters and leaves each block):</p><ul>' +
      line('A', cov & 1, rays.a_front[i], rays.a_back[i]) +
      line('B', cov & 2, rays.b_front[i], rays.b_back[i]) + '</ul>';
    h += '<form id="predict-form"><table><tr><th>after pass</th><th>stencil (0-15)</th></tr>';
    PASSES.forEach(function (p, k) {
      h += '<tr><td>' + esc(p.title) + '</td><td><input type="number" min="0" max="15" ' +
        'step="1" id="predict-stencil-' + (k + 1) + '" required> <span class="bits" ' +
        'id="predict-bits-' + (k + 1) + '"></span></td></tr>';
    });
    h += '<tr><td>the case read back</td><td><select id="predict-case" required>' +
      '<option value="">choose</option>';
    for (let c = 0; c <= 8; ++c) h += '<option value="' + c + '">case ' + c + '</option>';
    h += '<option value="-1">not examined (outside the MOR)</option></select></td></tr>';
    h += '</table>';
    h += '<details id="predict-rules"><summary>The rules of the passes and of the ' +
      'read-back</summary><ol>' + PASSES.concat([DECODE]).map(function (p) {
      return '<li><b>' + esc(p.title) + '</b>: ' + esc(p.rule) + '</li>';
    }).join('') + '</ol><p>Depth tests compare 24-bit values; equal depths pass both LEQUAL ' +
      'and GEQUAL. The stencil test 1 &le; count reads bits 0-1 only.</p></details>';
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

  function render() {
    const panel = $('predict');
    let h = '<h2>Predict</h2><p>Each exercise poses the blocks and chooses a pixel; the ' +
      'buffers are hidden until you answer. Predict the stencil after each pass and the case, ' +
      'then check.</p><div id="predict-list-wrap">' + listHtml() + '</div>';
    if (current) {
      const practises = current.exercise.sections.map(function (n) {
        return SECTIONS[n] + ' (' + n + ')';
      }).join(', ');
      h += '<div id="predict-exercise"><h3>' + esc(current.exercise.title) + '</h3><p>' +
        current.exercise.intro + '</p><p class="practises">Practises ' + practises +
        ': docs/algorithm.md, and the page\u2019s sections below once answered.</p>' +
        question(page.rayData, current.index,
          current.pixel[0], current.pixel[1]) + '</div>';
    } else if (choosing) {
      h += '<div id="predict-exercise"><h3>Your own pixel</h3><p>' +
        EXERCISES[EXERCISES.length - 1].intro + '</p></div>';
    }
    panel.innerHTML = h;
    bindList();
    if (!current) return;
    PASSES.forEach(function (p, k) {
      const input = $('predict-stencil-' + (k + 1));
      input.addEventListener('input', function () {
        const v = Number(input.value);
        $('predict-bits-' + (k + 1)).textContent =
          input.value !== '' && v >= 0 && v <= 15 ? 'binary ' + v.toString(2).padStart(4, '0') : '';
      });
    });
    $('predict-form').addEventListener('submit', function (ev) {
      ev.preventDefault();
      const answers = {stencil: PASSES.map(function (p, k) {
        return $('predict-stencil-' + (k + 1)).value;
      }), kase: $('predict-case').value === '' ? NaN : Number($('predict-case').value)};
      showVerdict(check(answers));
    });
    $('predict-close').addEventListener('click', close);
  }

  function bindList() {
    $('predict').querySelectorAll('[data-exercise]').forEach(function (b) {
      b.addEventListener('click', function () { start(b.dataset.exercise); });
    });
  }

  // A wrong answer shows its pass's section (text and pictures, the pixel marked by the ray
  // inspector's mark) under the feedback; a right one shows every section again.
  function showVerdict(v) {
    document.querySelectorAll('#live-result section.shown').forEach(function (s) {
      s.classList.remove('shown');
    });
    let h = '<p class="' + (v.correct ? 'right' : 'wrong') + '" id="predict-verdict">' +
      esc(v.message) + '</p>';
    if (!v.correct) {
      h += '<p id="predict-rule"><b>The rule of ' + esc(v.title) + ':</b> ' + esc(v.rule) + '</p>';
      const section = document.getElementById(v.stepId);
      if (section) {
        section.classList.add('shown');
        h += '<p>That pass\u2019s section is shown below the controls; try again.</p>';
      }
    } else {
      document.body.classList.remove('predicting');
      h += '<p>The buffers are shown again; the ray inspector has the pixel\u2019s whole ' +
        'story.</p>';
      $('predict-list-wrap').innerHTML = listHtml();
      bindList();
    }
    $('predict-feedback').innerHTML = h;
  }

  // --- opening and leaving an exercise ------------------------------------------------------

  function start(id) {
    const e = EXERCISES.find(function (x) { return x.id === id; });
    if (!e) throw new Error('no exercise ' + id);
    current = null;
    choosing = false;
    document.body.classList.add('predicting');
    if (e.pick.own) {
      choosing = true;
      render();
      return;
    }
    page.load({blocks: e.blocks, axis: 'z', resolution: 64, mor: e.mor,
      boxTest: e.boxTest !== false});
    pending = e;
    render();
  }

  function open(e, pixel, rays) {
    current = {exercise: e, pixel: [pixel[0], pixel[1]], index: pixel[2],
      truth: truthAt(rays, pixel[2]), signature: page.signature()};
    page.showRay([pixel[0], pixel[1]]);
    render();
  }

  function close() {
    current = null;
    choosing = false;
    pending = null;
    document.body.classList.remove('predicting');
    document.querySelectorAll('#live-result section.shown').forEach(function (s) {
      s.classList.remove('shown');
    });
    page.showRay(null);
    render();
  }

  // After every update of the page: an exercise whose pose just ran gets its pixel; one whose
  // pose the student changed is closed (its answer would no longer be this pose's).
  page.onUpdate.push(function (rays) {
    if (pending) {
      const e = pending;
      pending = null;
      const p = choosePixel(e.pick, rays);
      if (!p) {
        document.body.classList.remove('predicting');
        $('predict').querySelector('#predict-exercise') ||
          $('predict').insertAdjacentHTML('beforeend', '<div id="predict-exercise"></div>');
        $('predict-exercise').innerHTML = '<p class="wrong">This pose has no pixel for the ' +
          'exercise (the reference no longer gives it): please report it.</p>';
        return;
      }
      open(e, p, rays);
      return;
    }
    if (current && current.signature !== page.signature()) close();
  });

  // The own-pixel exercise: a click on the silhouettes picture (the only one shown) picks it.
  document.addEventListener('click', function (ev) {
    if (!choosing) return;
    const img = ev.target.closest && ev.target.closest('#live-result [data-region]');
    if (!img) return;
    const rays = page.rayData;
    const r = img.dataset.region.split(',').map(Number);
    const b = img.getBoundingClientRect();
    const x = r[0] + Math.floor((ev.clientX - b.left) / b.width * (r[2] - r[0]));
    const y = r[3] - 1 - Math.floor((ev.clientY - b.top) / b.height * (r[3] - r[1]));
    if (!rays.steps.length) {
      $('predict-exercise').insertAdjacentHTML('beforeend', '<p class="wrong">No pass ran on ' +
        'this pose (the box test found the blocks apart): move them together, or switch the ' +
        'box test off, and click again.</p>');
      return;
    }
    const i = page.rayIndex(x, y);
    if (i < 0) {
      $('predict-exercise').insertAdjacentHTML('beforeend', '<p class="wrong">No ray data at (' +
        x + ', ' + y + '): choose a pixel in [' + rays.crop.join(', ') + ') (the MOR and a ' +
        'margin).</p>');
      return;
    }
    choosing = false;
    open(EXERCISES[EXERCISES.length - 1], [x, y, i], rays);
  }, true);

  render();
  return {
    exercises: EXERCISES, passes: PASSES, start: start, close: close, check: check,
    current: function () { return current; }, progress: function () { return progress; },
    choosePixel: choosePixel,
  };
})();
