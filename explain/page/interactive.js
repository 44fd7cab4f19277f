// The interactive explain page (`recode explain --interactive`): two blocks a student shapes,
// drags and turns, and on every change the pair runs again in the reference compiled to
// WebAssembly (wasm/, recode_page), which answers with `recode pair --json`'s object, the explain
// page's sections for this run (the same text, legends and pictures as `recode explain`), and
// the ray inspector's data. The scene the page runs is a scene file, shown and exported as
// such, so that `recode pair` on the exported file gives the page's answer.
(function () {
  'use strict';
  const SHAPES = {
    cone: {radius: 1, height: 2},
    cylinder: {radius: 1, height: 2},
    capped_cone: {radius0: 0.6, radius1: 0.3, height: 2},
    sphere: {radius: 1},
    ellipsoid: {radii: [1, 0.6, 0.4]},
    box: {size: [1, 1, 1]},
    obj: {},  // a dropped OBJ file: the convex hull of its vertices
  };
  const common = window.recodeCommon;
  const PLANE = common.PLANE, AXES = common.AXES;
  const state = {
    blocks: [
      {name: 'A', shape: 'cone', sizes: {radius: 1, height: 2}, position: [0, 0, 0],
       rotation: [0, 0, 0], obj: null},
      {name: 'B', shape: 'cone', sizes: {radius: 1, height: 2}, position: [0, 0, 3.75],
       rotation: [180, 0, 0], obj: null},
    ],
    axis: 'x', resolution: 256, mor: 'min', boxTest: true, drag: 1, sweepAxis: 'z', sweep: 0,
    sweepRange: 1.5,
  };
  const $ = function (id) { return document.getElementById(id); };
  let module = null, runPage = null, lastError = null;
  let dirty = true, playing = false, playDirection = 1;
  let drag = null;  // a drag on a picture in progress (see "dragging a block" below)
  let view3d = null, rayPixel = null, fixedRay = false, rayMarks = true;
  const page = window.recodePage = {ready: false, error: null, pair: null, rayData: null,
    scene3d: null, sceneText: sceneText, state: state, update: update, load: load, pose: pose,
    signature: signature, showRay: showRay, rayIndex: rayIndex, morOf: morOf, view3d: null,
    onUpdate: [],  // functions called with the ray data after every update (page/predict.js)
    pending: function () { return dirty || drag !== null || playing; },
    // What the tests and the timing read: the updates run, the last one's time in ms (the
    // module's share apart) and every update's.
    metrics: {updates: 0, lastMs: 0, moduleMs: 0, times: []}};

  function number(v) { return Math.round(v * 1e6) / 1e6; }

  // How far the slider has moved block `index` from its position: along the sweep axis for B
  // (the block the slider and Play move), nothing for A.
  function sweepOffset(index) {
    const o = [0, 0, 0];
    if (index === 1) o[AXES.indexOf(state.sweepAxis)] = state.sweep * state.sweepRange;
    return o;
  }

  // Where block `index` is: its position plus the slider's offset. Its position fields show
  // this, and the scene file (what the page runs and Export saves) has it.
  function placed(index) {
    const o = sweepOffset(index);
    return state.blocks[index].position.map(function (v, k) { return number(v + o[k]); });
  }

  // The block's node of the scene file, where the block is placed.
  function objectOf(b, index) {
    const o = {name: b.name};
    if (b.shape === 'obj') {
      o.mesh = b.name + '.obj';
      o.hull = true;
    } else {
      o.shape = Object.assign({type: b.shape}, b.sizes);
    }
    o.position = placed(index);
    if (b.rotation.some(function (r) { return r !== 0; })) o.rotation_deg = b.rotation.map(number);
    return o;
  }

  function sceneText() {
    const scene = {view: {axis: state.axis, resolution: [state.resolution, state.resolution]},
      objects: state.blocks.map(objectOf)};
    return JSON.stringify(scene, null, 2) + '\n';
  }

  // What the page runs: the scene file and the options that change the answer.
  function signature() { return sceneText() + state.mor + state.boxTest; }

  // The pose and options as load() takes them back (an exercise keeps the one it replaced).
  function pose() {
    return JSON.parse(JSON.stringify({blocks: state.blocks, axis: state.axis,
      resolution: state.resolution, mor: state.mor, boxTest: state.boxTest, sweep: state.sweep,
      sweepAxis: state.sweepAxis, sweepRange: state.sweepRange}));
  }

  // Another pose and options (an exercise's, or pose()'s): the blocks, view axis, resolution,
  // MOR and box test; the sweep as given, else back to 0. The controls show them and the next
  // frame runs them.
  function load(s) {
    if (s.blocks) state.blocks = JSON.parse(JSON.stringify(s.blocks));
    ['axis', 'resolution', 'mor', 'boxTest', 'sweepAxis', 'sweepRange'].forEach(function (k) {
      if (s[k] !== undefined && s[k] !== null) state[k] = s[k];
    });
    state.sweep = s.sweep || 0;
    buildControls();
    changed();
  }

  // The MOR the reference finds for this pose in `mode` (min, max or full): [x0, y0, x1, y1],
  // or null where it is empty (the box test found the blocks apart). A run of the module of its
  // own: the page's pictures and ray data are copies, so they stay as they are.
  function morOf(mode) {
    if (!module) return null;
    module.FS.writeFile('/page/scene.json', sceneText());
    const answer = runPage(JSON.stringify({scene: '/page/scene.json', mor: mode,
      box_test: state.boxTest}));
    if (!answer) throw new Error('the MOR of mode ' + mode + ': ' + lastError());
    const m = JSON.parse(module.UTF8ToString(answer)).pair.mor;
    return m[2] > m[0] && m[3] > m[1] ? m : null;
  }

  // Runs the pair on the current scene; paints what the module answers.
  function update() {
    dirty = false;
    if (!module) return;
    const waiting = state.blocks.filter(function (b) { return b.shape === 'obj' && !b.obj; });
    if (waiting.length) {  // nothing to run yet: say so, instead of showing the last pose
      page.error = 'Block ' + waiting.map(function (b) { return b.name; }).join(' and ') +
        ' has the shape obj but no OBJ file yet: choose one with its file field or drop one ' +
        'on its panel (or choose another shape). The pictures below are of the last pose ' +
        'that ran.';
      $('live-error').textContent = page.error;
      $('live-error').hidden = false;
      return;
    }
    const started = performance.now();
    const text = sceneText();
    module.FS.writeFile('/page/scene.json', text);
    state.blocks.forEach(function (b) {
      if (b.shape === 'obj' && b.obj) module.FS.writeFile('/page/' + b.name + '.obj', b.obj);
    });
    const request = JSON.stringify({scene: '/page/scene.json', mor: state.mor,
      box_test: state.boxTest});
    const answer = runPage(request);
    const moduleMs = performance.now() - started;
    $('scene-text').value = text;
    $('pair-command').textContent = 'recode pair scene.json --mor ' + state.mor +
      (state.boxTest ? '' : ' --no-box-test');
    if (!answer) {
      page.error = lastError();
      $('live-error').textContent = page.error;
      $('live-error').hidden = false;
      return;
    }
    $('live-error').hidden = true;
    page.error = null;
    const result = JSON.parse(module.UTF8ToString(answer));
    // Parsed in a template, whose pictures do not load: each <img> names a picture that is not
    // a file but a canvas painted from the module's memory.
    const parsed = document.createElement('template');
    parsed.innerHTML = result.body;
    paintPictures(parsed.content, result.pictures);
    $('live-result').replaceChildren(parsed.content);
    page.rayData = rayData(result);
    window.recodeInspector.attach(page.rayData);
    page.pair = result.pair;
    page.scene3d = result.scene3d;
    showSummary(result.pair);
    if (view3d) {
      view3d.setScene(sceneOf(result.scene3d));
      drawRay();
    }
    page.onUpdate.forEach(function (f) { f(page.rayData); });
    const ms = performance.now() - started;
    const m = page.metrics;
    m.updates += 1;
    m.lastMs = ms;
    m.moduleMs = moduleMs;
    m.times.push({resolution: state.resolution, ms: ms, module_ms: moduleMs});
    $('update-ms').textContent = ms.toFixed(1) + ' ms (the pair and its pictures in WebAssembly: ' +
      moduleMs.toFixed(1) + ' ms)';
  }

  // The inspector's data: the module's JSON and its per-pixel arrays, copied out of the
  // module's memory as typed arrays under the names ray_arrays.order gives them, in its order
  // (per_step: one array per step), so that they read like the static page's JSON arrays.
  function rayData(result) {
    const d = result.ray_data, arrays = result.ray_arrays;
    const n = arrays.pixels, steps = d.steps.length;
    const count = arrays.order.reduce(function (sum, a) { return sum + (a.per_step ? steps : 1); },
      0);
    const all = new Int32Array(module.HEAPU8.buffer, arrays.offset, n * count).slice();
    let at = 0;
    const next = function () { at += n; return all.subarray(at - n, at); };
    arrays.order.forEach(function (a) {
      if (!a.per_step) { d[a.name] = next(); return; }
      d[a.name] = [];
      for (let k = 0; k < steps; ++k) d[a.name].push(next());
    });
    return d;
  }

  // Each <img> of the module's body becomes a canvas holding the kept picture (RGB rows from
  // the top, in the module's memory until the next update), enlarged by the browser.
  function paintPictures(root, pictures) {
    const heap = module.HEAPU8;
    pictures.forEach(function (p) {
      const img = root.querySelector('img[src="' + p.file + '"]');
      if (!img) return;
      const canvas = document.createElement('canvas');
      canvas.width = p.width;
      canvas.height = p.height;
      const image = new ImageData(p.width, p.height);
      const rgba = image.data;
      for (let i = 0, j = p.offset, n = p.width * p.height; i < n; ++i, j += 3) {
        rgba[4 * i] = heap[j];
        rgba[4 * i + 1] = heap[j + 1];
        rgba[4 * i + 2] = heap[j + 2];
        rgba[4 * i + 3] = 255;
      }
      canvas.getContext('2d').putImageData(image, 0, 0);
      const scale = Math.max(1, Math.floor(384 / Math.max(p.width, p.height)));
      canvas.style.width = (p.width * scale) + 'px';
      canvas.dataset.region = img.dataset.region;
      canvas.className = 'live-picture';
      canvas.title = img.alt + ': drag to move block ' + state.blocks[state.drag].name +
        ', shift-drag to turn it';
      img.replaceWith(canvas);
    });
  }

  function showSummary(pair) {
    $('live-verdict').textContent = pair.collide ? 'collide' : 'apart';
    $('live-verdict').className = 'verdict ' + (pair.collide ? 'yes' : 'no');
    let row = '<tr><th><a href="#term-cases">case</a></th>';
    let counts = '<tr><th>pixels</th>';
    common.CASES.forEach(function (c) {
      row += '<th>' + c + '</th>';
      counts += '<td data-case="' + c + '">' + pair.case_counts[String(c)] + '</td>';
    });
    $('case-counts').innerHTML = row + '</tr>' + counts + '</tr>';
    $('live-interfering').innerHTML = pair.interfering_pixels + ' <a href="#term-interfering">' +
      'interfering pixels</a> (cases ' + common.INTERFERING.join(', ') + ': the ray passes ' +
      'through a point inside both blocks), frame ' + pair.frame.resolution.join(' x ') +
      ' along ' + pair.frame.axis;
  }

  // --- the 3-D view (page/scene3d.js) ---------------------------------------------------------

  function sceneOf(s) {
    return {axis: s.axis, window: s.window, resolution: s.resolution, depthRange: s.depth_range,
      mor: s.mor, blocks: s.blocks};
  }

  // Where pixel (x, y) is in the ray data's per-pixel arrays (rows of the crop, bottom row
  // first), or -1 outside the crop, where the page has no data.
  function rayIndex(x, y) { return common.cropIndex(page.rayData, x, y); }

  // The ray through `rayPixel` with where it enters and leaves each block: the 24-bit depths
  // the inspector shows (the reference's own face depths), so that the picture and the
  // buffers agree. Outside the inspector's crop the page has no depths: the line alone.
  function drawRay() {
    if (!view3d) return;
    const d = page.rayData;
    if (!rayPixel || !d) { view3d.setRay(null); return; }
    const x = rayPixel[0], y = rayPixel[1];
    const i = rayMarks ? rayIndex(x, y) : -1;
    const on = function (bit) { return i >= 0 && common.covers(d.coverage[i], bit); };
    view3d.setRay({pixel: [x, y],
      a: on(common.COVER_A) ? [d.a_front[i], d.a_back[i]] : null,
      b: on(common.COVER_B) ? [d.b_front[i], d.b_back[i]] : null});
  }

  // A pixel chosen by the page (an exercise), or null: the ray follows the inspector again.
  // marks false: the ray without its entry and exit points (an exercise that asks for them).
  function showRay(pixel, marks) {
    fixedRay = pixel !== null;
    rayPixel = fixedRay ? pixel : window.recodeInspector.pixel();
    rayMarks = marks !== false;
    drawRay();
  }

  // The ray follows the inspector's pixel, so the view and the inspector's table are about the
  // same ray (unless the page fixed the ray).
  function followInspector() {
    window.recodeInspector.onPixel(function (p) {
      if (fixedRay) return;
      rayPixel = p;
      drawRay();
    });
  }

  function setUpView3d() {
    const canvas = $('view3d');
    try {
      view3d = page.view3d = window.recodeScene3d(canvas, $('view3d-scale'));
    } catch (e) {
      $('view3d-note').textContent = 'No 3-D view in this browser: ' + e.message;
      canvas.hidden = true;
      return;
    }
    const shown = {A: true, B: true, axes: true, window: true, mor: true, ray: true};
    const names = {A: 'block A', B: 'block B', axes: 'view axis', window: 'window', mor: 'MOR',
      ray: 'ray'};
    const options = $('view3d-options');
    Object.keys(shown).forEach(function (k) {
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = true;
      box.id = 'view3d-show-' + k;
      box.addEventListener('change', function () {
        const v = {};
        v[k] = box.checked;
        view3d.setVisible(v);
      });
      options.appendChild(field(names[k], box));
    });
    const along = document.createElement('button');
    along.type = 'button';
    along.id = 'view3d-along';
    along.textContent = 'Look along the view axis';
    along.addEventListener('click', function () { view3d.lookAlongAxis(); });
    options.appendChild(along);
    followInspector();
  }

  // --- the controls --------------------------------------------------------------------------

  function field(label, input) {
    const l = document.createElement('label');
    l.textContent = label + ' ';
    l.appendChild(input);
    return l;
  }

  function numberInput(value, step, onChange, id) {
    const i = document.createElement('input');
    i.type = 'number';
    i.step = String(step);
    i.value = String(value);
    if (id) i.id = id;
    i.addEventListener('change', function () {
      const v = Number(i.value);
      if (Number.isFinite(v)) { onChange(v); changed(); }
    });
    return i;
  }

  function select(options, value, onChange, id) {
    const s = document.createElement('select');
    options.forEach(function (o) {
      const e = document.createElement('option');
      e.value = String(o);
      e.textContent = String(o);
      s.appendChild(e);
    });
    s.value = String(value);
    if (id) s.id = id;
    s.addEventListener('change', function () { onChange(s.value); changed(); });
    return s;
  }

  function vectorInputs(vector, step, idPrefix) {
    const span = document.createElement('span');
    vector.forEach(function (v, k) {
      span.appendChild(numberInput(v, step, function (x) { vector[k] = x; }, idPrefix + AXES[k]));
    });
    return span;
  }

  // The block's position fields: where it is placed (B with the slider's offset). A value
  // typed places the block there, the slider keeping its offset.
  function positionInputs(index) {
    const b = state.blocks[index];
    const span = document.createElement('span');
    placed(index).forEach(function (v, k) {
      span.appendChild(numberInput(v, 0.05, function (x) {
        b.position[k] = number(x - sweepOffset(index)[k]);
      }, 'pos-' + b.name + '-' + AXES[k]));
    });
    return span;
  }

  // The position fields after the blocks moved (the slider, Play, a drag): where each block is
  // now. The field being typed in is left alone.
  function showPlacement() {
    state.blocks.forEach(function (b, index) {
      placed(index).forEach(function (v, k) {
        const input = $('pos-' + b.name + '-' + AXES[k]);
        if (input && input !== document.activeElement) input.value = String(v);
      });
    });
  }

  function blockControls(b, index) {
    const box = document.createElement('fieldset');
    box.id = 'block-' + b.name;
    const legend = document.createElement('legend');
    legend.textContent = 'Block ' + b.name;
    box.appendChild(legend);
    box.appendChild(field('shape', select(Object.keys(SHAPES), b.shape, function (v) {
      b.shape = v;
      b.sizes = JSON.parse(JSON.stringify(SHAPES[v]));
      buildControls();
    }, 'shape-' + b.name)));
    const sizes = document.createElement('div');
    Object.keys(b.sizes).forEach(function (key) {
      const v = b.sizes[key];
      sizes.appendChild(field(key, Array.isArray(v)
        ? vectorInputs(v, 0.1, 'size-' + b.name + '-' + key + '-')
        : numberInput(v, 0.1, function (x) { b.sizes[key] = x; }, 'size-' + b.name + '-' + key)));
    });
    if (b.shape === 'obj') {
      const file = document.createElement('input');
      file.type = 'file';
      file.accept = '.obj';
      file.addEventListener('change', function () {
        if (file.files.length) readObj(b, file.files[0]);
      });
      sizes.appendChild(field(b.obj ? 'OBJ loaded; another' : 'OBJ file (or drop one here)', file));
    }
    box.appendChild(sizes);
    box.appendChild(field('position', positionInputs(index)));
    box.appendChild(field('rotation (degrees)',
      vectorInputs(b.rotation, 5, 'rot-' + b.name + '-')));
    box.addEventListener('dragover', function (ev) { ev.preventDefault(); });
    box.addEventListener('drop', function (ev) {
      ev.preventDefault();
      if (ev.dataTransfer.files.length) readObj(b, ev.dataTransfer.files[0]);
    });
    return box;
  }

  function readObj(b, file) {
    file.text().then(function (text) {
      b.shape = 'obj';
      b.sizes = {};
      b.obj = text;
      buildControls();
      changed();
    });
  }

  function viewControls() {
    const box = document.createElement('fieldset');
    const legend = document.createElement('legend');
    legend.textContent = 'View and passes';
    box.appendChild(legend);
    box.appendChild(field('view axis', select(AXES, state.axis, function (v) { state.axis = v; },
      'view-axis')));
    box.appendChild(field('resolution', select([64, 128, 256, 512], state.resolution,
      function (v) { state.resolution = Number(v); }, 'resolution')));
    box.appendChild(field('MOR', select(['min', 'max', 'full'], state.mor,
      function (v) { state.mor = v; }, 'mor')));
    const boxTest = document.createElement('input');
    boxTest.type = 'checkbox';
    boxTest.id = 'box-test';
    boxTest.checked = state.boxTest;
    boxTest.addEventListener('change', function () { state.boxTest = boxTest.checked; changed(); });
    box.appendChild(field('box test (off: the passes run even when the boxes are apart)',
      boxTest));
    box.appendChild(field('drag moves block', select(['A', 'B'], state.blocks[state.drag].name,
      function (v) { state.drag = v === 'A' ? 0 : 1; }, 'drag-block')));
    const sweep = document.createElement('input');
    sweep.type = 'range';
    sweep.id = 'sweep';
    sweep.min = '-1';
    sweep.max = '1';
    sweep.step = '0.01';
    sweep.value = String(state.sweep);
    sweep.addEventListener('input', function () { state.sweep = Number(sweep.value); changed(); });
    const through = document.createElement('div');
    through.appendChild(field('move B along', select(AXES, state.sweepAxis,
      function (v) { state.sweepAxis = v; }, 'sweep-axis')));
    through.appendChild(field('by \u00b1', numberInput(state.sweepRange, 0.1,
      function (v) { state.sweepRange = Math.abs(v); }, 'sweep-range')));
    through.appendChild(sweep);
    const play = document.createElement('button');
    play.id = 'play';
    play.textContent = playing ? 'Stop' : 'Play';
    play.addEventListener('click', function () {
      playing = !playing;
      play.textContent = playing ? 'Stop' : 'Play';
    });
    through.appendChild(play);
    box.appendChild(through);
    return box;
  }

  function buildControls() {
    const c = $('live-controls');
    c.innerHTML = '';
    state.blocks.forEach(function (b, i) { c.appendChild(blockControls(b, i)); });
    c.appendChild(viewControls());
  }

  // Anything changed: the next frame runs the pair again; the position fields show where the
  // blocks now are.
  function changed() {
    dirty = true;
    showPlacement();
  }

  // --- dragging a block over any picture ----------------------------------------------------

  document.addEventListener('pointerdown', function (ev) {
    const canvas = ev.target.closest && ev.target.closest('#live-result canvas[data-region]');
    if (!canvas || !page.pair || ev.button !== 0) return;
    const r = canvas.dataset.region.split(',').map(Number);
    const frame = page.pair.frame;
    const bounds = canvas.getBoundingClientRect();
    const b = state.blocks[state.drag];
    drag = {x: ev.clientX, y: ev.clientY, moved: false, turn: ev.shiftKey, block: b,
      position: b.position.slice(), rotation: b.rotation.slice(), axis: frame.axis,
      // world units per CSS pixel, along the picture's width and height
      du: (frame.window[2] - frame.window[0]) / frame.resolution[0] * (r[2] - r[0]) / bounds.width,
      dv: (frame.window[3] - frame.window[1]) / frame.resolution[1] * (r[3] - r[1]) / bounds.height};
    ev.preventDefault();
  });
  window.addEventListener('pointermove', function (ev) {
    if (!drag) return;
    const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 2) drag.moved = true;
    if (!drag.moved) return;
    const b = drag.block;
    if (drag.turn) {  // about the view axis: the angle of that axis
      const k = AXES.indexOf(drag.axis);
      b.rotation[k] = number(drag.rotation[k] - dx * 0.5);
    } else {
      const plane = PLANE[drag.axis];
      b.position = drag.position.slice();
      b.position[AXES.indexOf(plane[0])] = number(drag.position[AXES.indexOf(plane[0])] + dx * drag.du);
      b.position[AXES.indexOf(plane[1])] = number(drag.position[AXES.indexOf(plane[1])] - dy * drag.dv);
    }
    changed();
  });
  window.addEventListener('pointerup', function () {
    if (!drag) return;
    const moved = drag.moved;
    drag = null;
    if (!moved) return;
    buildControls();  // the inputs show the new pose
    // The click that ends a drag does not pin a pixel in the inspector.
    const swallow = function (ev) { ev.preventDefault(); };
    document.addEventListener('click', swallow, true);
    setTimeout(function () { document.removeEventListener('click', swallow, true); }, 50);
  });

  // --- export ----------------------------------------------------------------------------------

  function download(name, text) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], {type: 'application/json'}));
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
  }

  $('export').addEventListener('click', function () {
    download('scene.json', sceneText());
    state.blocks.forEach(function (b) {
      if (b.shape === 'obj' && b.obj) download(b.name + '.obj', b.obj);
    });
  });

  // --- the loop ----------------------------------------------------------------------------------

  function frame() {
    if (playing) {
      let s = state.sweep + 0.01 * playDirection;
      if (s > 1 || s < -1) { playDirection = -playDirection; s = Math.max(-1, Math.min(1, s)); }
      state.sweep = number(s);
      const slider = $('sweep');
      if (slider) slider.value = String(state.sweep);
      changed();
    }
    if (dirty) {
      try {
        update();
      } catch (e) {
        page.error = String(e);
        console.error(e);
      }
    }
    requestAnimationFrame(frame);
  }

  buildControls();
  setUpView3d();
  createRecodeModule().then(function (m) {
    module = m;
    module.FS.mkdirTree('/page');
    runPage = module.cwrap('recode_page', 'number', ['string']);
    lastError = module.cwrap('recode_error', 'string', []);
    update();
    page.ready = true;
    $('live-status').textContent = 'ready: change anything, drag a picture';
    requestAnimationFrame(frame);
  }, function (e) {
    $('live-status').textContent = 'the WebAssembly module did not load: ' + e;
    console.error(e);
  });
})();
