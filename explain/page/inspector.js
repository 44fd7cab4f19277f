// The explain page's ray inspector. It reads the ray data (the inline JSON of `recode explain`'s
// page, or what the interactive page hands it after every change), follows the pointer over
// every picture (each <img> or <canvas> carries the frame rectangle it shows in data-region),
// and describes each step at the pixel from the recorded buffers: the depth and stencil after
// the step are the recorded values; which test passed and which stencil operation ran are read
// off the step's state and the recorded values before and after. Needs page/common.js.
window.recodeInspector = (function () {
  'use strict';
  let data = {steps: []};
  let D = 1;
  const panel = document.getElementById('inspector-body');
  const slider = document.getElementById('step-slider');
  const stepName = document.getElementById('step-name');
  let ids = [];
  const common = window.recodeCommon;
  const esc = common.esc, inRect = common.inRect, covers = common.covers;
  let TITLES = {};  // each step's name by its id, from the ray data
  let pixel = null;
  let pinned = false;
  let step = 0;
  const idleHtml = panel.innerHTML;  // what the panel says while no pixel is chosen
  const pixelListeners = [];  // told the pixel shown (or null) whenever it changes

  // Shows pixel p ([x, y], or null: none) and tells the listeners; `pin`: keep it while the
  // pointer moves elsewhere.
  function choose(p, pin) {
    const same = p && pixel ? p[0] === pixel[0] && p[1] === pixel[1] : p === pixel;
    pixel = p ? [p[0], p[1]] : null;
    pinned = pin && pixel !== null;
    if (pixel) show(); else panel.innerHTML = idleHtml;
    markAll();
    if (!same) pixelListeners.forEach(function (f) { f(pixel && pixel.slice()); });
  }

  function index(x, y) { return common.cropIndex(data, x, y); }
  function norm(d) { return (d / D).toFixed(6); }
  function bin(v) { return v.toString(2).padStart(4, '0'); }

  // What the step did at pixel i: [test outcome, stencil operation], HTML.
  function describe(k, i, x, y) {
    const id = ids[k];
    const before = k > 0 ? data.stencil[k - 1][i] : 0;
    const after = data.stencil[k][i];
    const stored = k > 0 ? data.depth[k - 1][i] : 0;
    const cov = data.coverage[i];
    const hasA = covers(cov, common.COVER_A), hasB = covers(cov, common.COVER_B);
    const count = common.countOf(before);
    if (id !== 'contact_near' && id !== 'contact_far' && id !== 'read_stencil' &&
        !inRect(data.mor, x, y))
      return ['outside the MOR: the scissor keeps the step off this pixel', 'none'];
    switch (id) {
      case 'set_z':
        return hasA
          ? ['depth cleared to 0, then GEQUAL: each fragment of A at or behind the stored depth ' +
             'passes, the last one left is A<sub>max</sub>', 'REPLACE: stencil = 1 (A is here)']
          : ['no fragment of A: nothing drawn, depth stays at the clear value 0', 'none: stencil stays 0'];
      case 'test_z': {
        if (!hasB) return ['no fragment of B on this ray', 'none'];
        if (count < 1) return ['stencil test 1 &le; count fails (count 0: A absent)', 'KEEP (sfail)'];
        const f = data.b_front[i] <= stored, b = data.b_back[i] <= stored;
        const n = (f ? 1 : 0) + (b ? 1 : 0);
        let t = 'stencil test 1 &le; count passes; depth LEQUAL A<sub>max</sub> ' + norm(stored) +
          ': B front ' + norm(data.b_front[i]) + (f ? ' passes' : ' fails') + ', B back ' +
          norm(data.b_back[i]) + (b ? ' passes' : ' fails');
        if (common.countOf(count + n) !== common.countOf(after))
          t += ' <span class="warn">(recorded count ' + common.countOf(after) + ': more than one fragment of a face here)</span>';
        return [t, n === 0 ? 'KEEP (dpfail) twice' : 'INCR &times;' + n + ' &rarr; count ' + common.countOf(after)];
      }
      case 'load_amin':
        return hasA
          ? ['depth cleared to 1, then LEQUAL: the nearest fragment of A stays, A<sub>min</sub>',
             'KEEP (write mask 0: the count survives)']
          : ['no fragment of A: depth stays at the clear value 1', 'KEEP (write mask 0)'];
      case 'test_amin_front':
      case 'test_amin_back': {
        const front = id === 'test_amin_front';
        const bit = front ? common.FRONT_BIT : common.BACK_BIT;
        const face = front ? data.b_front[i] : data.b_back[i];
        const flipped = ((before ^ after) & bit) !== 0;
        const label = front ? 'B front (B<sub>min</sub>)' : 'B back (B<sub>max</sub>)';
        if (!hasB) return ['no face of B on this ray', 'none: bit ' + (front ? 2 : 3) + ' stays'];
        if (count < 1)
          return ['stencil test 1 &le; count fails (A absent)',
                  'INVERT (sfail): bit ' + (front ? 2 : 3) + ' ' + (flipped ? 'set: B is here' : 'unchanged')];
        const pass = face >= stored;
        return ['depth GEQUAL A<sub>min</sub> ' + norm(stored) + ': ' + label + ' ' + norm(face) +
                (pass ? ' passes (at or behind A<sub>min</sub>)' : ' fails (in front of A<sub>min</sub>)'),
                pass ? 'INVERT: bit ' + (front ? 2 : 3) + (flipped ? ' set' : ' unchanged') : 'KEEP (dpfail)'];
      }
      case 'read_stencil':
        return inRect(data.mor, x, y)
          ? ['stencil ' + after + ' (binary ' + bin(after) + ') read back', 'decoded: case ' + data['case'][i]]
          : ['outside the MOR: not read', 'none'];
      case 'contact_near':
      case 'contact_far': {
        const near = id === 'contact_near';
        if (!inRect(data.contact_rect, x, y))
          return ['outside the contact rectangle: untouched', 'none'];
        return [near ? 'depth cleared to 0; front faces of A and B with GEQUAL: max(A<sub>min</sub>, B<sub>min</sub>)'
                     : 'depth cleared to 1; back faces of A and B with LEQUAL: min(A<sub>max</sub>, B<sub>max</sub>)',
                'KEEP (write mask 0)'];
      }
    }
    return ['', ''];
  }

  // The ray as a drawing: the viewer on the left, depth growing to the right, stretched
  // over the depths this pixel has; A's and B's intervals, and the depth buffer after the
  // chosen step.
  function rayDrawing(i, k) {
    const cov = data.coverage[i];
    const hasA = covers(cov, common.COVER_A), hasB = covers(cov, common.COVER_B);
    const vals = [];
    if (hasA) vals.push(data.a_front[i], data.a_back[i]);
    if (hasB) vals.push(data.b_front[i], data.b_back[i]);
    const dk = data.depth[k][i];
    if (dk !== 0 && dk !== D) vals.push(dk);
    let lo = vals.length ? Math.min.apply(null, vals) : 0;
    let hi = vals.length ? Math.max.apply(null, vals) : D;
    const pad = Math.max((hi - lo) * 0.15, 2);
    lo = Math.max(0, lo - pad); hi = Math.min(D, hi + pad);
    const W = 470, L = 80, R = 400;
    const X = function (d) { return L + (R - L) * (d - lo) / Math.max(1, hi - lo); };
    let s = '<svg id="ray-svg" xmlns="http://www.w3.org/2000/svg" width="' + W + '" height="150" ' +
      'viewBox="0 0 ' + W + ' 150" role="img" aria-label="the ray through the pixel">';
    s += '<text x="4" y="20" font-size="11">viewer</text>';
    s += '<polygon points="22,28 34,34 22,40" fill="#333"/>';
    s += '<line x1="' + L + '" y1="34" x2="' + R + '" y2="34" stroke="#333" stroke-dasharray="4 3"/>';
    s += '<text x="' + (R - 60) + '" y="24" font-size="11">ray, depth &#8594;</text>';
    // The entry depth under the bar's left end (anchored there, to the left), the exit under
    // its right end (to the right), so that the two never overlap.
    const bar = function (y, a, b, colour, name) {
      const x0 = X(a), x1 = X(b);
      return '<rect x="' + x0 + '" y="' + y + '" width="' + Math.max(2, x1 - x0) + '" height="16" fill="' +
        colour + '" opacity="0.85"/><text x="4" y="' + (y + 12) + '" font-size="12" font-weight="bold">' +
        name + '</text><text x="' + x0 + '" y="' + (y + 29) + '" font-size="10" text-anchor="end">' +
        norm(a) + '</text><text x="' + (x1 + 2) + '" y="' + (y + 29) + '" font-size="10">' + norm(b) + '</text>';
    };
    s += hasA ? bar(46, data.a_front[i], data.a_back[i], '#3a78d8', 'A')
              : '<text x="4" y="58" font-size="12">A: not on this ray</text>';
    s += hasB ? bar(86, data.b_front[i], data.b_back[i], '#d64545', 'B')
              : '<text x="4" y="98" font-size="12">B: not on this ray</text>';
    const dx = X(Math.min(hi, Math.max(lo, dk)));
    s += '<line x1="' + dx + '" y1="40" x2="' + dx + '" y2="130" stroke="#0a0" stroke-width="2"/>';
    s += '<text x="' + Math.min(dx + 3, 250) + '" y="144" font-size="11" fill="#060">depth after ' +
      esc(TITLES[ids[k]] || ids[k]) + ': ' + norm(dk) + (dk < lo || dk > hi ? ' (off the drawing)' : '') + '</text>';
    s += '<text x="' + L + '" y="12" font-size="10" fill="#666">drawn from depth ' + norm(lo) +
      ' to ' + norm(hi) + ' (stretched to this ray)</text>';
    s += '</svg>';
    return s;
  }

  function show() {
    if (!pixel) return;
    const x = pixel[0], y = pixel[1];
    const i = index(x, y);
    let h = '<h3 id="inspector-title">pixel (' + x + ', ' + y + ')</h3>';
    if (i < 0 || ids.length === 0) {
      panel.innerHTML = h + '<p>No ray data here: the page keeps the values of the pixels ' +
        'in [' + data.crop.join(', ') + ') only (the MOR and a margin' +
        (data.capped ? ', cut to ' + data.max_pixels + ' pixels' : '') + ').</p>';
      return;
    }
    const c = data['case'][i];
    h += '<p class="case-big" id="inspector-case">' + (c < 0 ? 'outside the MOR: not examined'
      : 'case ' + c + ': ' + esc(data.case_names[c]) + (common.interferes(c) ? ' (interferes)' : '')) + '</p>';
    h += rayDrawing(i, step);
    h += '<table id="inspector-passes"><tr><th>step</th><th>depth after</th><th>stencil after</th>' +
      '<th>test</th><th>stencil op</th></tr>';
    for (let k = 0; k < ids.length; ++k) {
      const d = describe(k, i, x, y);
      const v = data.stencil[k][i], dv = data.depth[k][i];
      h += '<tr data-step="' + ids[k] + '"' + (k === step ? ' class="now"' : '') + '><td>' +
        esc(TITLES[ids[k]] || ids[k]) + '</td><td class="depth">' + dv + ' (' + norm(dv) +
        ')</td><td class="stencil">' + v + ' (' + bin(v) + ')</td><td>' + d[0] + '</td><td>' + d[1] + '</td></tr>';
    }
    h += '</table>';
    panel.innerHTML = h;
  }

  function showStep() {
    stepName.textContent = ids.length ? (TITLES[ids[step]] || ids[step]) : 'no passes';
    document.querySelectorAll('section.now').forEach(function (s) { s.classList.remove('now'); });
    const sec = ids.length ? document.getElementById(ids[step]) : null;
    if (sec) sec.classList.add('now');
    show();
  }

  function markAll() {
    document.querySelectorAll('.pic').forEach(function (w) {
      const img = w.querySelector('[data-region]');
      const m = w.querySelector('.mark');
      const r = img.dataset.region.split(',').map(Number);
      if (!pixel || !inRect(r, pixel[0], pixel[1])) { m.style.display = 'none'; return; }
      const fw = r[2] - r[0], fh = r[3] - r[1];
      m.style.display = 'block';
      m.style.left = (100 * (pixel[0] - r[0]) / fw) + '%';
      m.style.top = (100 * (r[3] - 1 - pixel[1]) / fh) + '%';
      m.style.width = Math.max(100 / fw, 1) + '%';
      m.style.height = Math.max(100 / fh, 1) + '%';
    });
  }

  function pixelOf(ev, img) {
    const r = img.dataset.region.split(',').map(Number);
    const b = img.getBoundingClientRect();
    const fx = (ev.clientX - b.left) / b.width, fy = (ev.clientY - b.top) / b.height;
    const x = r[0] + Math.floor(fx * (r[2] - r[0]));
    const y = r[3] - 1 - Math.floor(fy * (r[3] - r[1]));
    return [Math.min(r[2] - 1, Math.max(r[0], x)), Math.min(r[3] - 1, Math.max(r[1], y))];
  }

  // Wraps every picture not wrapped yet with its pixel mark and follows the pointer over it.
  function bindPictures() {
    document.querySelectorAll('[data-region]').forEach(function (img) {
      if (img.parentNode.classList.contains('pic')) return;
      const w = document.createElement('span');
      w.className = 'pic';
      img.parentNode.insertBefore(w, img);
      w.appendChild(img);
      const m = document.createElement('div');
      m.className = 'mark';
      w.appendChild(m);
      img.addEventListener('mousemove', function (ev) {
        if (pinned || ev.buttons) return;
        choose(pixelOf(ev, img), false);
      });
      img.addEventListener('click', function (ev) {
        if (ev.defaultPrevented) return;  // the end of a drag, not a click on a pixel
        choose(pixelOf(ev, img), true);
      });
    });
  }

  // A pixel chosen by the page (an exercise's): pinned, shown and marked, whatever was pinned
  // before; null: no pixel (the panel says how to choose one), follow the pointer again.
  function showPixel(p) { choose(p, true); }

  // f(pixel) after every change of the pixel shown: [x, y], or null when none is.
  function onPixel(f) { pixelListeners.push(f); }

  // New ray data and pictures (the interactive page after every change): the step and a pixel
  // still inside the frame are kept, so that one ray can be watched while a block moves.
  function attach(newData) {
    const atLast = step >= ids.length - 1;
    data = newData;
    D = data.depth_max;
    TITLES = common.stepWords(data).names;
    ids = data.steps.map(function (s) { return s.id; });
    step = ids.length === 0 ? 0 : (atLast ? ids.length - 1 : Math.min(step, ids.length - 1));
    slider.max = String(Math.max(0, ids.length - 1));
    slider.value = String(step);
    bindPictures();
    markAll();
    showStep();
  }

  slider.addEventListener('input', function () { step = Number(slider.value); showStep(); });
  document.addEventListener('keydown', function (ev) {
    if (ev.target && ev.target.tagName === 'INPUT' && ev.target !== slider) return;
    if (ev.target && (ev.target.tagName === 'SELECT' || ev.target.tagName === 'TEXTAREA')) return;
    if (ev.key === 'Escape') { pinned = false; return; }
    if (ev.target === slider) return;  // the slider moves itself
    let d = 0;
    if (ev.key === 'ArrowRight' || ev.key === 'ArrowDown' || ev.key === 'n') d = 1;
    if (ev.key === 'ArrowLeft' || ev.key === 'ArrowUp' || ev.key === 'p') d = -1;
    if (d === 0 || ids.length === 0) return;
    ev.preventDefault();
    step = Math.min(ids.length - 1, Math.max(0, step + d));
    slider.value = String(step);
    showStep();
  });
  const inline = document.getElementById('ray-data');
  if (inline) attach(JSON.parse(inline.textContent));
  return {attach: attach, showPixel: showPixel, onPixel: onPixel,
    pixel: function () { return pixel && pixel.slice(); }};
})();
