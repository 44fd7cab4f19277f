// WebGPU's own depth/stencil pipeline, the page half of backends/webgpu/native/native_backend.py.
// Unlike ../page/webgpu_replay.js (WGSL shaders that apply the contract), nothing here computes
// coverage, depth or a stencil op: the vertex shader only moves the 24.8 fixed-point window
// coordinates into clip space, and the browser's rasterizer, depth interpolation and
// depth/stencil state (depth32float-stencil8) do the rest. What comes back is what WebGPU gives.
'use strict';

(function () {
  const FORMAT = 'depth32float-stencil8';
  const COMPARE = {NEVER: 'never', LESS: 'less', EQUAL: 'equal', LEQUAL: 'less-equal',
                   GREATER: 'greater', NOTEQUAL: 'not-equal', GEQUAL: 'greater-equal',
                   ALWAYS: 'always'};
  const STENCIL_OP = {KEEP: 'keep', ZERO: 'zero', REPLACE: 'replace', INCR: 'increment-clamp',
                      INCR_WRAP: 'increment-wrap', DECR: 'decrement-clamp',
                      DECR_WRAP: 'decrement-wrap', INVERT: 'invert'};
  const CULL = {none: 'none', front: 'front', back: 'back'};

  // The window coordinates of a vertex, X and Y in 1/256 pixel, reach the rasterizer exactly:
  // the render target is P x Q with P, Q powers of two and the viewport is all of it, so
  // x_ndc = (X - 256 x0) * 2/(256 P) - 1 is a power-of-two scaling and a subtraction whose result
  // has fewer than 24 significant bits (|X| <= 2^23), and the viewport transform
  // (x_ndc + 1) * P/2 gives back X/256 - x0. Likewise y, which WebGPU's framebuffer counts down:
  // y_fb = Q - (Y/256 - y0). z is the vertex's float depth, w = 1: no other arithmetic.
  const WGSL = `
struct Tile { scale: vec2f, origin: vec2i }
@group(0) @binding(0) var<uniform> tile: Tile;

@vertex fn windowVertex(@location(0) xy: vec2i, @location(1) z: f32) -> @builtin(position) vec4f {
  let p = vec2f(xy - tile.origin) * tile.scale - vec2f(1.0, 1.0);
  return vec4f(p, z, 1.0);
}

// A clear: one triangle over the whole target (the scissor and the write masks limit it).
struct ClearOut { @builtin(position) position: vec4f, @location(0) @interpolate(flat) depth: f32 }
@vertex fn clearVertex(@builtin(vertex_index) i: u32, @location(1) z: f32) -> ClearOut {
  var corners = array(vec2f(-1.0, -1.0), vec2f(3.0, -1.0), vec2f(-1.0, 3.0));
  return ClearOut(vec4f(corners[i], 0.5, 1.0), z);
}
@fragment fn clearFragment(v: ClearOut) -> @builtin(frag_depth) f32 {
  return v.depth;
}
`;

  const page = {ready: false};
  window.recodeNative = page;
  let device, shader, layout, bindGroupLayout;
  const pipelines = new Map();

  const keep = {compare: 'always', failOp: 'keep', depthFailOp: 'keep', passOp: 'keep'};

  function stencilFace(s, ops) {
    return {compare: COMPARE[s.stencil_func], failOp: STENCIL_OP[ops[0]],
            depthFailOp: STENCIL_OP[ops[1]], passOp: STENCIL_OP[ops[2]]};
  }

  // The WebGPU state of each kind of step. A draw: the contract's state as it is. A depth clear:
  // the value written everywhere in the scissor, through the depth write mask, no stencil. A
  // stencil clear: the value replaces the stencil through the write mask, no depth.
  function depthStencil(kind, s) {
    if (kind === 'draw')
      return {format: FORMAT, depthWriteEnabled: s.depth_write,
              depthCompare: COMPARE[s.depth_func], stencilFront: stencilFace(s, s.front_ops),
              stencilBack: stencilFace(s, s.back_ops), stencilReadMask: s.stencil_value_mask,
              stencilWriteMask: s.stencil_write_mask};
    if (kind === 'clear_depth')
      return {format: FORMAT, depthWriteEnabled: s.depth_write, depthCompare: 'always',
              stencilFront: keep, stencilBack: keep, stencilWriteMask: 0};
    const replace = {compare: 'always', failOp: 'keep', depthFailOp: 'keep', passOp: 'replace'};
    return {format: FORMAT, depthWriteEnabled: false, depthCompare: 'always',
            stencilFront: replace, stencilBack: replace, stencilWriteMask: s.stencil_write_mask};
  }

  // One pipeline per state combination, made once and kept for the whole run.
  function pipelineFor(kind, s) {
    const ds = depthStencil(kind, s);
    const cull = kind === 'draw' ? CULL[s.cull] : 'none';
    const key = kind + cull + JSON.stringify(ds);
    let p = pipelines.get(key);
    if (p)
      return p;
    const draw = kind === 'draw';
    const desc = {
      layout: layout,
      vertex: {module: shader, entryPoint: draw ? 'windowVertex' : 'clearVertex',
               buffers: draw ? [{arrayStride: 12, attributes: [
                 {shaderLocation: 0, offset: 0, format: 'sint32x2'},
                 {shaderLocation: 1, offset: 8, format: 'float32'}]}]
                 : [{arrayStride: 4, stepMode: 'instance', attributes: [
                   {shaderLocation: 1, offset: 0, format: 'float32'}]}]},
      primitive: {topology: 'triangle-list', frontFace: 'ccw', cullMode: cull},
      depthStencil: ds};
    if (kind === 'clear_depth')
      desc.fragment = {module: shader, entryPoint: 'clearFragment', targets: []};
    p = device.createRenderPipeline(desc);
    pipelines.set(key, p);
    return p;
  }

  page.init = async function () {
    if (!navigator.gpu)
      throw new Error('navigator.gpu is missing: this browser exposes no WebGPU');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter)
      throw new Error('no WebGPU adapter');
    if (!adapter.features.has(FORMAT))
      throw new Error('the WebGPU adapter lacks ' + FORMAT);
    device = await adapter.requestDevice({requiredFeatures: [FORMAT], requiredLimits: {
      maxTextureDimension2D: adapter.limits.maxTextureDimension2D}});
    device.addEventListener('uncapturederror', (e) => console.error('WebGPU: ' + e.error.message));
    shader = device.createShaderModule({code: WGSL});
    const info = await shader.getCompilationInfo();
    for (const m of info.messages)
      if (m.type === 'error')
        throw new Error('WGSL line ' + m.lineNum + ': ' + m.message);
    bindGroupLayout = device.createBindGroupLayout({entries: [{
      binding: 0, visibility: GPUShaderStage.VERTEX, buffer: {type: 'uniform'}}]});
    layout = device.createPipelineLayout({bindGroupLayouts: [bindGroupLayout]});
    const i = adapter.info || {};
    page.adapter = [i.vendor, i.architecture, i.device, i.description].filter((x) => x)
        .join(' ') || 'unknown';
    page.maxTexture = device.limits.maxTextureDimension2D;
    page.ready = true;
    return {adapter: page.adapter, maxTexture: page.maxTexture};
  };

  // The steps of a command stream: the state each draw and clear runs with (the contract's
  // section 6 defaults first), every draw's vertices and indices gathered into one buffer each.
  function stepsOf(w, h, commands) {
    const s = {scissor: [0, 0, w, h], depth_func: 'LESS', depth_write: true,
               stencil_func: 'ALWAYS', stencil_ref: 0, stencil_value_mask: 255,
               front_ops: ['KEEP', 'KEEP', 'KEEP'], back_ops: ['KEEP', 'KEEP', 'KEEP'],
               stencil_write_mask: 255, cull: 'none'};
    const steps = [], vertices = [], indices = [], clears = [];
    let vertexCount = 0;
    for (const c of commands) {
      switch (c.op) {
        case 'scissor': {
          const [x0, y0, x1, y1] = c.rect;
          s.scissor = [Math.max(x0, 0), Math.max(y0, 0), Math.min(x1, w), Math.min(y1, h)];
          break;
        }
        case 'depth_func': s.depth_func = c.func; break;
        case 'depth_write_mask': s.depth_write = c.write; break;
        case 'stencil_func':
          s.stencil_func = c.func;
          s.stencil_ref = c.ref;
          s.stencil_value_mask = c.value_mask;
          break;
        case 'stencil_ops': {
          const ops = [c.sfail, c.dpfail, c.dppass];
          if (c.face !== 'back')
            s.front_ops = ops;
          if (c.face !== 'front')
            s.back_ops = ops;
          break;
        }
        case 'stencil_write_mask': s.stencil_write_mask = c.mask; break;
        case 'cull': s.cull = c.mode; break;
        case 'clear_depth':
        case 'clear_stencil':
          steps.push({kind: c.op, s: Object.assign({}, s), clear: clears.length,
                      ref: c.op === 'clear_stencil' ? c.value : 0});
          clears.push(c.op === 'clear_depth' ? c.value : 0);
          break;
        case 'draw':
          if (c.indices.length)
            steps.push({kind: 'draw', s: Object.assign({}, s), firstIndex: indices.length,
                        count: c.indices.length, baseVertex: vertexCount, ref: s.stencil_ref});
          for (const v of c.vertices_fixed)
            vertices.push(v);
          for (const i of c.indices)
            indices.push(i);
          vertexCount += c.vertices_fixed.length;
          break;
        default:
          throw new Error('unknown command ' + JSON.stringify(c.op));
      }
    }
    return {steps, vertices, indices, clears};
  }

  function buffer(usage, bytes) {
    const b = device.createBuffer({size: Math.max(4, Math.ceil(bytes.byteLength / 4) * 4),
                                   usage, mappedAtCreation: true});
    new Uint8Array(b.getMappedRange()).set(new Uint8Array(bytes.buffer, bytes.byteOffset,
                                                          bytes.byteLength));
    b.unmap();
    return b;
  }

  const align256 = (n) => Math.ceil(n / 256) * 256;
  const pow2AtLeast = (n) => {
    let p = 1;
    while (p < n)
      p *= 2;
    return p;
  };

  // Runs one request: `w` x `h`, the golden file's commands. Answers the depth aspect's floats
  // and the stencil bytes, bottom row first, base64.
  page.run = async function (w, h, commands) {
    const {steps, vertices, indices, clears} = stepsOf(w, h, commands);
    const vertexBytes = new ArrayBuffer(Math.max(vertices.length, 1) * 12);
    const xy = new Int32Array(vertexBytes), z = new Float32Array(vertexBytes);
    vertices.forEach((v, k) => {
      xy[3 * k] = v[0];
      xy[3 * k + 1] = v[1];
      z[3 * k + 2] = v[2];
    });
    const gpu = {
      vertices: buffer(GPUBufferUsage.VERTEX, new Uint8Array(vertexBytes)),
      indices: buffer(GPUBufferUsage.INDEX, Uint32Array.from(indices)),
      clears: buffer(GPUBufferUsage.VERTEX, Float32Array.from(clears.length ? clears : [0]))};
    const depth = new Float32Array(w * h), stencil = new Uint8Array(w * h);
    // Tiles only where the frame exceeds the device's largest texture.
    let size = 1;
    while (size * 2 <= device.limits.maxTextureDimension2D)
      size *= 2;
    for (let y0 = 0; y0 < h; y0 += size)
      for (let x0 = 0; x0 < w; x0 += size)
        await drawTile(w, steps, gpu, [x0, y0, Math.min(x0 + size, w), Math.min(y0 + size, h)],
                       depth, stencil);
    for (const b of Object.values(gpu))
      b.destroy();
    return {depth: base64(new Uint8Array(depth.buffer)), stencil: base64(stencil)};
  };

  function base64(bytes) {
    let text = '';
    for (let i = 0; i < bytes.length; i += 0x8000)
      text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(text);
  }

  // Draws every step into the tile [x0, x1) x [y0, y1) of the frame and copies the tile's
  // depth and stencil into `depth` and `stencil` (frame-sized, bottom row first).
  async function drawTile(frameWidth, steps, gpu, tile, depth, stencil) {
    const [tx0, ty0, tx1, ty1] = tile;
    const tw = tx1 - tx0, th = ty1 - ty0;
    const P = pow2AtLeast(tw), Q = pow2AtLeast(th);
    const u = new ArrayBuffer(16);
    new Float32Array(u, 0, 2).set([2 / (256 * P), 2 / (256 * Q)]);
    new Int32Array(u, 8, 2).set([256 * tx0, 256 * ty0]);
    const uniforms = buffer(GPUBufferUsage.UNIFORM, new Uint8Array(u));
    const bindGroup = device.createBindGroup({
      layout: bindGroupLayout, entries: [{binding: 0, resource: {buffer: uniforms}}]});
    const target = device.createTexture({size: [P, Q], format: FORMAT,
        usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC});
    const encoder = device.createCommandEncoder();
    // The fresh framebuffer: depth 1.0, stencil 0.
    const pass = encoder.beginRenderPass({colorAttachments: [], depthStencilAttachment: {
      view: target.createView(), depthClearValue: 1.0, depthLoadOp: 'clear',
      depthStoreOp: 'store', stencilClearValue: 0, stencilLoadOp: 'clear',
      stencilStoreOp: 'store'}});
    pass.setBindGroup(0, bindGroup);
    pass.setIndexBuffer(gpu.indices, 'uint32');
    for (const step of steps) {
      // The scissor within the tile, in the target's rows (counted from its top).
      const x0 = Math.max(step.s.scissor[0], tx0), y0 = Math.max(step.s.scissor[1], ty0);
      const x1 = Math.min(step.s.scissor[2], tx1), y1 = Math.min(step.s.scissor[3], ty1);
      if (x1 <= x0 || y1 <= y0)
        continue;
      pass.setPipeline(pipelineFor(step.kind, step.s));
      pass.setScissorRect(x0 - tx0, Q - (y1 - ty0), x1 - x0, y1 - y0);
      pass.setStencilReference(step.ref);
      if (step.kind === 'draw') {
        pass.setVertexBuffer(0, gpu.vertices);
        pass.drawIndexed(step.count, 1, step.firstIndex, step.baseVertex, 0);
      } else {
        pass.setVertexBuffer(0, gpu.clears);
        pass.draw(3, 1, 0, step.clear);
      }
    }
    pass.end();
    // A depth or stencil aspect is copied whole (WebGPU allows no part of one); the tile is its
    // bottom-left tw x th, the target's rows Q - th .. Q - 1.
    const depthRow = align256(P * 4), stencilRow = align256(P);
    const depthOut = device.createBuffer({size: depthRow * Q,
        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
    const stencilOut = device.createBuffer({size: stencilRow * Q,
        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
    encoder.copyTextureToBuffer({texture: target, aspect: 'depth-only'},
                                {buffer: depthOut, bytesPerRow: depthRow}, [P, Q]);
    encoder.copyTextureToBuffer({texture: target, aspect: 'stencil-only'},
                                {buffer: stencilOut, bytesPerRow: stencilRow}, [P, Q]);
    device.queue.submit([encoder.finish()]);
    await Promise.all([depthOut.mapAsync(GPUMapMode.READ), stencilOut.mapAsync(GPUMapMode.READ)]);
    const d = new Float32Array(depthOut.getMappedRange());
    const st = new Uint8Array(stencilOut.getMappedRange());
    for (let j = ty0; j < ty1; ++j) {
      const r = Q - 1 - (j - ty0);  // the frame's row j (from the bottom) is the target's row r
      depth.set(d.subarray(r * depthRow / 4, r * depthRow / 4 + tw), j * frameWidth + tx0);
      stencil.set(st.subarray(r * stencilRow, r * stencilRow + tw), j * frameWidth + tx0);
    }
    depthOut.unmap();
    stencilOut.unmap();
    for (const b of [depthOut, stencilOut, uniforms])
      b.destroy();
    target.destroy();
  }
})();
