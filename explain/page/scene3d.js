// scene3d.js: a small WebGL2 viewer of one RECODE frame in 3-D: the blocks A and B as the frame's
// orthographic camera sees them (or turned, to see depth), the view axis, the frame's window, the
// MOR box, the ray through one pixel with where it enters and leaves each block, and a depth
// scale: ticks along the view axis labelled with its coordinate, drawn on a second canvas laid
// over the first (text is not WebGL's business). window.recodeScene3d(canvas, scaleCanvas)
// returns the view (see the object `view` below for its methods); it throws an Error where the
// browser gives no WebGL2. No libraries, no network. Needs page/common.js.
(function () {
  'use strict';

  const COLOURS = {A: window.recodeCommon.COLOURS.A, B: window.recodeCommon.COLOURS.B,
    background: [17, 17, 17]};
  const LINE = {axis: [205, 205, 205], window: [150, 150, 150], mor: [0, 229, 255],
    ray: [255, 210, 63], outline: [255, 255, 255]};
  const DEPTH_ONE = 16777215; // the largest 24-bit depth value; it stands for d = dmin
  const DEG_PER_PX = 0.5;
  const ZOOM_MIN = 0.05, ZOOM_MAX = 100;
  const MARKER_HALF_PX = 3.5, OUTLINE_HALF_PX = 5; // a white ring shows a marker on its block

  // Image-plane coordinate k of (u, v, d) is world component PERM[axis][k]. All three are cyclic
  // permutations, i.e. rotations, so (u, v, d) is right-handed like (x, y, z): triangles that are
  // counter-clockwise from outside stay so, and a camera with u right and v up looks toward -d.
  const PERM = window.recodeCommon.PERM;
  const SCALE_TICKS = 8;       // about this many labelled ticks over the depth range
  const SCALE_LABEL_PX = 28;   // labels at least this far apart on the screen
  const SCALE_MIN_PX = 4;      // ticks closer than this: the axis points at the viewer

  const BLOCK_VS = `#version 300 es
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uMvp;
uniform mat3 uTurn;
out vec3 vNormal;
void main() {
  vNormal = uTurn * aNormal;
  gl_Position = uMvp * vec4(aPos, 1.0);
}`;

  // A light just off the viewing direction (eye space): faces toward the viewer keep nearly the
  // block colour, turned faces darken, and abs() lights inside faces too (two-sided lighting).
  const BLOCK_FS = `#version 300 es
precision highp float;
in vec3 vNormal;
uniform vec3 uColour;
out vec4 outColour;
void main() {
  vec3 light = normalize(vec3(0.3, 0.45, 1.0));
  float lambert = abs(dot(normalize(vNormal), light));
  outColour = vec4(uColour * (0.6 + 0.4 * lambert), 1.0);
}`;

  const LINE_VS = `#version 300 es
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aColour;
uniform mat4 uMvp;
out vec3 vColour;
void main() {
  vColour = aColour;
  gl_Position = uMvp * vec4(aPos, 1.0);
}`;

  const LINE_FS = `#version 300 es
precision highp float;
in vec3 vColour;
out vec4 outColour;
void main() { outColour = vec4(vColour, 1.0); }`;

  const IDENTITY = new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);

  function compile(gl, vsText, fsText) {
    const program = gl.createProgram();
    for (const [type, text] of [[gl.VERTEX_SHADER, vsText], [gl.FRAGMENT_SHADER, fsText]]) {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, text);
      gl.compileShader(shader);
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
        throw new Error('recodeScene3d: shader: ' + gl.getShaderInfoLog(shader));
      }
      gl.attachShader(program, shader);
      gl.deleteShader(shader); // stays alive while attached
    }
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      throw new Error('recodeScene3d: program: ' + gl.getProgramInfoLog(program));
    }
    return program;
  }

  // One buffer of interleaved vec3 pairs (position, then normal or colour) and its VAO.
  function pairBuffer(gl) {
    const vao = gl.createVertexArray();
    const buffer = gl.createBuffer();
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    for (const loc of [0, 1]) {
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 24, loc * 12);
    }
    gl.bindVertexArray(null);
    return {vao, buffer};
  }

  function upload(gl, pair, data) {
    gl.bindBuffer(gl.ARRAY_BUFFER, pair.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, data, gl.DYNAMIC_DRAW); // same buffer, new storage: no leak
  }

  function finite(values, count, what) {
    if (!values || values.length !== count || !Array.from(values).every(Number.isFinite)) {
      throw new Error('recodeScene3d: ' + what + ' must be ' + count + ' finite numbers');
    }
    return Array.from(values, Number);
  }

  // A step of 1, 2, 2.5 or 5 times a power of ten giving about `count` steps over `span`.
  function niceStep(span, count) {
    const raw = span / count, p = Math.pow(10, Math.floor(Math.log10(raw)));
    return [1, 2, 2.5, 5, 10].map((m) => m * p).find((m) => m >= raw) || 10 * p;
  }

  window.recodeScene3d = function (canvas, scaleCanvas) {
    const gl = canvas.getContext('webgl2',
      {preserveDrawingBuffer: true, antialias: false, depth: true, alpha: false});
    if (!gl) throw new Error('recodeScene3d: this browser gives no WebGL2 context');
    const blockProgram = compile(gl, BLOCK_VS, BLOCK_FS);
    const lineProgram = compile(gl, LINE_VS, LINE_FS);
    const loc = {
      blockMvp: gl.getUniformLocation(blockProgram, 'uMvp'),
      blockTurn: gl.getUniformLocation(blockProgram, 'uTurn'),
      blockColour: gl.getUniformLocation(blockProgram, 'uColour'),
      lineMvp: gl.getUniformLocation(lineProgram, 'uMvp'),
    };
    const tris = pairBuffer(gl);
    const lines = pairBuffer(gl);
    const marks = pairBuffer(gl);

    let scene = null;     // the frame: axis, window, resolution, depthRange, centre, sizes
    let ray = null;
    let blockRanges = {}; // name -> [first vertex, count] in tris
    let lineGroups = {};  // axes | window | mor | ray -> [first vertex, count] in lines
    const visible = {A: true, B: true, axes: true, window: true, mor: true, ray: true};
    const cam = {yaw: 0, pitch: 0, zoom: 1};
    let frameRequest = 0;
    let ticks = [];       // the depth scale as last drawn: {value, world, px}

    // Image-plane coordinates relative to the scene centre, in doubles: positions far from the
    // origin keep their precision when they then go into a Float32Array.
    function local(world) {
      const p = PERM[scene.axis];
      return [world[p[0]] - scene.centre[0], world[p[1]] - scene.centre[1],
        world[p[2]] - scene.centre[2]];
    }
    function worldOf(u, v, d) {
      const out = [0, 0, 0];
      PERM[scene.axis].forEach((k, i) => { out[k] = [u, v, d][i]; });
      return out;
    }

    // The turn as a 3x3 (rows): Rx(pitch) * Ry(yaw). Yaw turns about v, the image plane's up;
    // pitch then tilts about the screen's horizontal.
    function turnRows() {
      const y = cam.yaw * Math.PI / 180;
      const p = cam.pitch * Math.PI / 180;
      const cy = Math.cos(y), sy = Math.sin(y), cp = Math.cos(p), sp = Math.sin(p);
      return [[cy, 0, sy], [sp * sy, cp, -sp * cy], [-cp * sy, sp, cp * cy]];
    }

    // Orthographic: the window's half-sizes fill the canvas at zoom 1, so looking along the axis
    // maps the window exactly onto the drawing buffer (non-uniformly if the aspects differ; the
    // turned views share that scale so that turning back meets lookAlongAxis without a jump).
    // Depth covers a sphere holding everything, whatever the turn; zoom leaves depth alone.
    function projectionRows() {
      const t = turnRows();
      const sx = cam.zoom / scene.half[0], sy = cam.zoom / scene.half[1];
      const sz = -1 / scene.depthRadius; // nearer (larger eye z) -> smaller depth
      return [t[0].map((e) => e * sx), t[1].map((e) => e * sy), t[2].map((e) => e * sz)];
    }

    function mvp() {
      const r = projectionRows();
      const m = new Float32Array(16);
      for (let c = 0; c < 3; c++) for (let row = 0; row < 3; row++) m[c * 4 + row] = r[row][c];
      m[15] = 1;
      return m;
    }

    function toPixel(localPoint) {
      const r = projectionRows();
      const dot = (row) => row[0] * localPoint[0] + row[1] * localPoint[1] + row[2] * localPoint[2];
      return [(dot(r[0]) + 1) * 0.5 * canvas.width, (1 - dot(r[1])) * 0.5 * canvas.height];
    }

    function uploadBlocks(blocks) {
      const all = new Float32Array(blocks.reduce((s, b) => s + (b.triangles || []).length * 6, 0));
      const ranges = {};
      let at = 0;
      blocks.forEach((block, index) => {
        const name = block.name || (index === 0 ? 'A' : 'B');
        const pos = block.positions, tri = block.triangles;
        if (!pos || pos.length % 3 || !tri || tri.length % 3) {
          throw new Error('recodeScene3d: block ' + name + ' needs positions and triangles ' +
            'in threes');
        }
        const n = pos.length / 3;
        const verts = [];
        for (let i = 0; i < n; i++) verts.push(local([pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]]));
        const data = all.subarray(at, at + tri.length * 6);
        for (let t = 0; t < tri.length; t += 3) {
          const abc = [tri[t], tri[t + 1], tri[t + 2]].map((k) => {
            if (!Number.isInteger(k) || k < 0 || k >= n) {
              throw new Error('recodeScene3d: block ' + name + ' has a bad vertex index ' + k);
            }
            return verts[k];
          });
          const [a, b, c] = abc;
          const e = [0, 1, 2].map((k) => b[k] - a[k]), f = [0, 1, 2].map((k) => c[k] - a[k]);
          const normal = [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
            e[0] * f[1] - e[1] * f[0]];
          const len = Math.hypot(normal[0], normal[1], normal[2]);
          // A degenerate triangle draws nothing; a unit normal keeps the shader free of NaNs.
          const unit = len > 0 ? normal.map((x) => x / len) : [0, 0, 1];
          abc.forEach((p, k) => data.set(p.concat(unit), (t + k) * 6));
        }
        for (const v of verts) scene.reach = Math.max(scene.reach, Math.hypot(v[0], v[1], v[2]));
        ranges[name] = [at / 6, tri.length];
        at += data.length;
      });
      blockRanges = ranges;
      upload(gl, tris, all);
    }

    // The line geometry, grouped so setVisible only chooses what to draw.
    function uploadLines() {
      const out = [];
      const groups = {};
      const [hu, hv, hd] = scene.half;
      const m = scene.margin;
      const seg = (p, q, colour) => {
        const c = colour.map((x) => x / 255);
        out.push(p[0], p[1], p[2], c[0], c[1], c[2], q[0], q[1], q[2], c[0], c[1], c[2]);
      };
      const group = (name, build) => {
        const first = out.length / 6;
        build();
        groups[name] = [first, out.length / 6 - first];
      };
      group('axes', () => {
        // From the viewer's side through the scene, the head pointing the way the camera looks.
        const tip = -hd - m, h = 0.4 * m;
        seg([0, 0, hd + m], [0, 0, tip], LINE.axis);
        for (const [a, b] of [[h, 0], [-h, 0], [0, h], [0, -h]]) {
          seg([0, 0, tip], [a, b, tip + 2 * h], LINE.axis);
        }
      });
      const rect = (u0, v0, u1, v1, d, colour) => {
        const corners = [[u0, v0, d], [u1, v0, d], [u1, v1, d], [u0, v1, d]];
        corners.forEach((p, k) => seg(p, corners[(k + 1) % 4], colour));
        return corners;
      };
      // The window sits on the viewer's side, where the camera's image plane is.
      group('window', () => rect(-hu, -hv, hu, hv, hd, LINE.window));
      group('mor', () => {
        if (!scene.mor) return;
        const [x0, y0, x1, y1] = scene.mor;
        const [umin, vmin, umax, vmax] = scene.window;
        const [W, H] = scene.resolution;
        const u = (x) => umin + x * (umax - umin) / W - scene.centre[0];
        const v = (y) => vmin + y * (vmax - vmin) / H - scene.centre[1];
        const near = rect(u(x0), v(y0), u(x1), v(y1), hd, LINE.mor);
        const far = rect(u(x0), v(y0), u(x1), v(y1), -hd, LINE.mor);
        near.forEach((p, k) => seg(p, far[k], LINE.mor));
      });
      group('ray', () => {
        if (!ray) return;
        const [u, v] = pixelCentre(ray.pixel).map((x, k) => x - scene.centre[k]);
        seg([u, v, hd + m], [u, v, -hd - m], LINE.ray);
      });
      lineGroups = groups;
      upload(gl, lines, new Float32Array(out));
    }

    // The spec's formulas, in its order of operations, so that a checker computing them in
    // doubles gets exactly these numbers.
    function pixelCentre(pixel) {
      const [umin, vmin, umax, vmax] = scene.window;
      const [W, H] = scene.resolution;
      return [umin + (pixel[0] + 0.5) * (umax - umin) / W,
        vmin + (pixel[1] + 0.5) * (vmax - vmin) / H];
    }

    function rayPoints() {
      if (!scene || !ray) return [];
      const [u, v] = pixelCentre(ray.pixel);
      const [dmin, dmax] = scene.depthRange;
      const points = [];
      for (const [block, pair] of [['A', ray.a], ['B', ray.b]]) {
        if (!pair) continue;
        pair.forEach((Z, k) => {
          const d = dmax - (Z / DEPTH_ONE) * (dmax - dmin);
          points.push({block, end: k ? 'exit' : 'enter', depth: Z, world: worldOf(u, v, d)});
        });
      }
      return points;
    }

    // Markers as screen-space squares in clip space: they need no point-size support and stay
    // the same size whatever the zoom.
    function markerData(points) {
      const out = [];
      const square = (px, py, half, colour) => {
        const c = colour.map((x) => x / 255);
        const x0 = (px - half) / canvas.width * 2 - 1, x1 = (px + half) / canvas.width * 2 - 1;
        const y0 = 1 - (py + half) / canvas.height * 2, y1 = 1 - (py - half) / canvas.height * 2;
        for (const [x, y] of [[x0, y0], [x1, y0], [x1, y1], [x0, y0], [x1, y1], [x0, y1]]) {
          out.push(x, y, 0, c[0], c[1], c[2]);
        }
      };
      const at = points.map((p) => toPixel(local(p.world)));
      // Outlines first, so that a marker's outline never covers another marker's colour.
      at.forEach(([px, py]) => square(px, py, OUTLINE_HALF_PX, LINE.outline));
      at.forEach(([px, py], k) => square(px, py, MARKER_HALF_PX, COLOURS[points[k].block]));
      return new Float32Array(out);
    }

    function drawRange(mode, range) {
      if (range && range[1] > 0) gl.drawArrays(mode, range[0], range[1]);
    }

    function draw() {
      const start = performance.now();
      if (frameRequest) cancelAnimationFrame(frameRequest); // this draw serves that request
      frameRequest = 0;
      if (gl.isContextLost()) return; // nothing to draw into; a lost context is not restored
      const bg = COLOURS.background.map((x) => x / 255);
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.clearColor(bg[0], bg[1], bg[2], 1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      if (scene) {
        const m = mvp();
        gl.enable(gl.DEPTH_TEST);
        gl.depthFunc(gl.LEQUAL);
        // Pushed back a little so the window and MOR lines lying on a face still show.
        gl.enable(gl.POLYGON_OFFSET_FILL);
        gl.polygonOffset(1, 1);
        gl.useProgram(blockProgram);
        gl.uniformMatrix4fv(loc.blockMvp, false, m);
        const t = turnRows();
        gl.uniformMatrix3fv(loc.blockTurn, false,
          new Float32Array([0, 1, 2].flatMap((c) => [t[0][c], t[1][c], t[2][c]])));
        gl.bindVertexArray(tris.vao);
        for (const name of ['A', 'B']) {
          if (!visible[name] || !blockRanges[name]) continue;
          gl.uniform3fv(loc.blockColour, COLOURS[name].map((x) => x / 255));
          drawRange(gl.TRIANGLES, blockRanges[name]);
        }
        gl.disable(gl.POLYGON_OFFSET_FILL);
        gl.useProgram(lineProgram);
        gl.uniformMatrix4fv(loc.lineMvp, false, m);
        gl.bindVertexArray(lines.vao);
        for (const name of ['axes', 'window', 'mor']) {
          if (visible[name]) drawRange(gl.LINES, lineGroups[name]);
        }
        // The ray and its markers on top: hidden inside an opaque block they would say nothing.
        gl.disable(gl.DEPTH_TEST);
        const points = visible.ray ? rayPoints() : [];
        if (visible.ray) drawRange(gl.LINES, lineGroups.ray);
        if (points.length) {
          const data = markerData(points);
          upload(gl, marks, data);
          gl.uniformMatrix4fv(loc.lineMvp, false, IDENTITY);
          gl.bindVertexArray(marks.vao);
          gl.drawArrays(gl.TRIANGLES, 0, data.length / 6);
        }
        gl.bindVertexArray(null);
      }
      drawScale();
      view.lastDrawMs = performance.now() - start;
      view.draws += 1;
    }

    // The depth scale: ticks on the view axis at round values of its coordinate, each labelled
    // with it, across the blocks' range along the axis. Looking along the axis they would all
    // fall on one point: then (and with the axis hidden) none are drawn.
    function drawScale() {
      ticks = [];
      const ctx = scaleCanvas ? scaleCanvas.getContext('2d') : null;
      if (ctx) ctx.clearRect(0, 0, scaleCanvas.width, scaleCanvas.height);
      if (!scene || !visible.axes) return;
      const [dmin, dmax] = scene.depthRange;
      const span = Math.max(dmax - dmin, 1e-9);
      const step = niceStep(span, SCALE_TICKS);
      const from = Math.ceil((dmin - 0.5 * scene.margin) / step - 1e-9);
      const to = Math.floor((dmax + 0.5 * scene.margin) / step + 1e-9);
      const name = scene.axis;
      const p0 = toPixel([0, 0, 0]), p1 = toPixel([0, 0, step]);
      const along = [p1[0] - p0[0], p1[1] - p0[1]];
      const len = Math.hypot(along[0], along[1]);
      if (len < SCALE_MIN_PX) return;
      const across = [-along[1] / len, along[0] / len];  // the tick's direction on the screen
      const every = [1, 2, 4, 10].find((n) => n * len >= SCALE_LABEL_PX) || 20;
      for (let k = from; k <= to; k++) {
        const value = Math.round(k * step * 1e9) / 1e9;
        const px = toPixel([0, 0, value - scene.centre[2]]);
        ticks.push({value, world: worldOf(scene.centre[0], scene.centre[1], value), px,
          labelled: k % every === 0});
        if (!ctx) continue;
        ctx.strokeStyle = 'rgb(255,255,255)';
        ctx.lineWidth = 1.5;
        ctx.beginPath();
        ctx.moveTo(px[0] - 5 * across[0], px[1] - 5 * across[1]);
        ctx.lineTo(px[0] + 5 * across[0], px[1] + 5 * across[1]);
        ctx.stroke();
        if (k % every !== 0) continue;
        ctx.fillStyle = 'rgb(255,255,255)';
        ctx.font = '11px sans-serif';
        ctx.fillText(name + ' ' + value, px[0] + 8 * across[0] + 2, px[1] + 8 * across[1] + 4);
      }
    }

    // Pointer moves come faster than frames: draw at most once a frame for them.
    function drawSoon() {
      if (!frameRequest) frameRequest = requestAnimationFrame(() => { frameRequest = 0; draw(); });
    }

    function turnBy(yawDeg, pitchDeg) {
      cam.yaw = ((cam.yaw + yawDeg) % 360 + 540) % 360 - 180;
      // Beyond straight up or down the drag direction would flip: stop there.
      cam.pitch = Math.max(-90, Math.min(90, cam.pitch + pitchDeg));
    }

    const view = {
      colours: COLOURS,
      lastDrawMs: 0,
      draws: 0,
      setScene(s) {
        if (!s || !PERM[s.axis]) throw new Error("recodeScene3d: axis must be 'x', 'y' or 'z'");
        const win = finite(s.window, 4, 'window');
        const res = finite(s.resolution, 2, 'resolution');
        const dr = finite(s.depthRange, 2, 'depthRange');
        if (!(win[2] > win[0] && win[3] > win[1] && res[0] > 0 && res[1] > 0 && dr[1] >= dr[0])) {
          throw new Error('recodeScene3d: empty window, resolution or depth range');
        }
        const axisChanged = !scene || scene.axis !== s.axis;
        const half = [(win[2] - win[0]) / 2, (win[3] - win[1]) / 2, (dr[1] - dr[0]) / 2];
        const reach = Math.hypot(half[0], half[1], half[2]);
        const previous = scene;
        scene = {
          axis: s.axis, window: win, resolution: res, depthRange: dr, half, reach,
          mor: s.mor ? finite(s.mor, 4, 'mor') : null,
          centre: [(win[0] + win[2]) / 2, (win[1] + win[3]) / 2, (dr[0] + dr[1]) / 2],
          margin: 0.15 * Math.max(2 * half[0], 2 * half[1], 2 * half[2]),
        };
        try {
          uploadBlocks(s.blocks || []); // widens scene.reach to the farthest vertex
        } catch (err) {
          scene = previous; // bad blocks leave the view as it was: nothing was uploaded yet
          throw err;
        }
        // Everything (the axis arrow and ray ends included) lies within reach + margin.
        scene.depthRadius = 1.05 * (scene.reach + scene.margin) || 1;
        uploadLines();
        if (axisChanged) Object.assign(cam, {yaw: 0, pitch: 0, zoom: 1});
        draw();
      },
      setRay(r) {
        ray = r ? {pixel: finite(r.pixel, 2, 'ray pixel'),
          a: r.a ? finite(r.a, 2, 'ray a') : null, b: r.b ? finite(r.b, 2, 'ray b') : null} : null;
        if (scene) uploadLines();
        draw();
      },
      rayPoints,
      scale: () => ticks.map((t) => ({value: t.value, world: t.world.slice(), px: t.px.slice(),
        labelled: t.labelled})),
      // A turn that shows depth: the view axis across the screen, the blocks seen a little from
      // above (the exercises open with it).
      lookFromSide() {
        Object.assign(cam, {yaw: 70, pitch: 15, zoom: 0.6});
        draw();
      },
      lookAlongAxis() {
        Object.assign(cam, {yaw: 0, pitch: 0, zoom: 1});
        draw();
      },
      turn(yawDeg, pitchDeg) {
        turnBy(Number(yawDeg) || 0, Number(pitchDeg) || 0);
        draw();
      },
      camera: () => ({yaw: cam.yaw, pitch: cam.pitch, zoom: cam.zoom}),
      project: (world) => (scene ? toPixel(local(world)) : null),
      setVisible(v) {
        for (const key of Object.keys(visible)) {
          if (v && typeof v[key] === 'boolean') visible[key] = v[key];
        }
        draw();
      },
      draw,
      readPixels() {
        const width = canvas.width, height = canvas.height;
        const raw = new Uint8Array(width * height * 4);
        gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
        const data = new Uint8Array(raw.length);
        const row = width * 4;
        for (let y = 0; y < height; y++) {
          data.set(raw.subarray((height - 1 - y) * row, (height - y) * row), y * row);
        }
        return {width, height, data};
      },
    };

    let drag = null;
    canvas.style.touchAction = 'none'; // a touch drag orbits instead of scrolling the page
    canvas.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      drag = {id: e.pointerId, x: e.clientX, y: e.clientY};
      try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* synthetic pointer */ }
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag || e.pointerId !== drag.id) return;
      turnBy((e.clientX - drag.x) * DEG_PER_PX, (e.clientY - drag.y) * DEG_PER_PX);
      Object.assign(drag, {x: e.clientX, y: e.clientY});
      drawSoon();
    });
    const endDrag = (e) => { if (drag && e.pointerId === drag.id) drag = null; };
    canvas.addEventListener('pointerup', endDrag);
    canvas.addEventListener('pointercancel', endDrag);
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault(); // zoom the view, not scroll the page
      const z = cam.zoom * Math.exp(-e.deltaY * (e.deltaMode === 1 ? 0.05 : 0.0015));
      cam.zoom = Math.max(ZOOM_MIN, Math.min(ZOOM_MAX, z));
      drawSoon();
    }, {passive: false});
    canvas.addEventListener('dblclick', () => view.lookAlongAxis());

    draw();
    return view;
  };
})();
