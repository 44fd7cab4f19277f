// The WebGPU back end's page half: replays the commands that the module's recode_gpu_commands
// prepares for a golden vector (proxy records, render states, clears) with WebGPU render
// pipelines, reads the depth and stencil aspects back and compares them with the vector's
// expected buffers bit for bit. The shaders (exact_contract32.wgsl + exact32_webgpu.wgsl) decide
// coverage and depth; this file only maps the contract's state onto WebGPU's.
'use strict';

(function () {
  const FORMAT = 'depth32float-stencil8';
  const RECORD_WORDS = 18;  // backends::ProxyTriangle: 72 bytes
  const DEPTH_MAX = 16777215;  // the initial depth buffer, as CpuDevice starts it
  const COMPARE = {NEVER: 'never', LESS: 'less', EQUAL: 'equal', LEQUAL: 'less-equal',
                   GREATER: 'greater', NOTEQUAL: 'not-equal', GEQUAL: 'greater-equal',
                   ALWAYS: 'always'};
  const STENCIL_OP = {KEEP: 'keep', ZERO: 'zero', REPLACE: 'replace', INCR: 'increment-clamp',
                      INCR_WRAP: 'increment-wrap', DECR: 'decrement-clamp',
                      DECR_WRAP: 'decrement-wrap', INVERT: 'invert'};

  const page = {ready: false, error: null};
  window.recodeWebgpu = page;
  let module, device, shader, layout, bindGroupLayout;
  const pipelines = new Map();

  function stencilFace(s, ops) {
    return {compare: COMPARE[s.stencil_func], failOp: STENCIL_OP[ops[0]],
            depthFailOp: STENCIL_OP[ops[1]], passOp: STENCIL_OP[ops[2]]};
  }

  // The depth-stencil state of each kind of command: a draw takes the contract's state as it
  // is; a depth clear writes depth everywhere in the scissor and no stencil; a stencil clear
  // replaces the stencil through the write mask and writes no depth (the reference's clears).
  function depthStencil(kind, s) {
    if (kind === 'draw')
      return {format: FORMAT, depthWriteEnabled: s.depth_write,
              depthCompare: COMPARE[s.depth_func], stencilFront: stencilFace(s, s.front_ops),
              stencilBack: stencilFace(s, s.back_ops), stencilReadMask: s.stencil_value_mask,
              stencilWriteMask: s.stencil_write_mask};
    const keep = {compare: 'always', failOp: 'keep', depthFailOp: 'keep', passOp: 'keep'};
    if (kind === 'clear_depth')
      return {format: FORMAT, depthWriteEnabled: true, depthCompare: 'always',
              stencilFront: keep, stencilBack: keep, stencilWriteMask: 0};
    const replace = {compare: 'always', failOp: 'keep', depthFailOp: 'keep', passOp: 'replace'};
    return {format: FORMAT, depthWriteEnabled: false, depthCompare: 'always',
            stencilFront: replace, stencilBack: replace,
            stencilWriteMask: s.stencil_write_mask};
  }

  // One pipeline per state combination, made once and kept across vectors.
  function pipelineFor(kind, s) {
    const ds = depthStencil(kind, s);
    const key = kind + JSON.stringify(ds);
    let p = pipelines.get(key);
    if (p)
      return p;
    const draw = kind === 'draw';
    const sint = (n) => n === 1 ? 'sint32' : 'sint32x' + n;
    const uint = (n) => 'uint32x' + n;
    p = device.createRenderPipeline({
      layout: layout,
      vertex: {module: shader, entryPoint: draw ? 'proxyVertex' : 'clearVertex',
               buffers: [{arrayStride: RECORD_WORDS * 4, stepMode: 'instance', attributes: [
                 {shaderLocation: 0, offset: 0, format: sint(4)},
                 {shaderLocation: 1, offset: 16, format: sint(4)},
                 {shaderLocation: 2, offset: 32, format: sint(2)},
                 {shaderLocation: 3, offset: 40, format: uint(3)},
                 {shaderLocation: 4, offset: 52, format: sint(1)},
                 {shaderLocation: 5, offset: 56, format: uint(4)}]}]},
      fragment: {module: shader, entryPoint: draw ? 'proxyFragment' : 'clearFragment',
                 targets: []},
      primitive: {topology: 'triangle-strip', frontFace: 'ccw', cullMode: 'none'},
      depthStencil: ds});
    pipelines.set(key, p);
    return p;
  }

  // A clear as one record: its rectangle is the scissor, its z0 the bits of q 2^-24.
  function clearRecord(s, q) {
    const r = new Uint32Array(RECORD_WORDS);
    r.set(s.scissor.map((v) => v >>> 0), 0);
    new Float32Array(r.buffer, 40, 1)[0] = q / 16777216;
    r[13] = 1;
    return r;
  }

  page.init = async function (wgsl) {
    module = await createRecodeModule();
    if (!navigator.gpu)
      throw new Error('navigator.gpu is missing: this browser exposes no WebGPU');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter)
      throw new Error('no WebGPU adapter');
    if (!adapter.features.has(FORMAT))
      throw new Error('the adapter lacks ' + FORMAT);
    // The adapter's largest texture, so that as few tiles as possible are drawn.
    device = await adapter.requestDevice({requiredFeatures: [FORMAT], requiredLimits: {
      maxTextureDimension2D: adapter.limits.maxTextureDimension2D}});
    device.addEventListener('uncapturederror', (e) => console.error('WebGPU: ' + e.error.message));
    shader = device.createShaderModule({code: wgsl});
    const info = await shader.getCompilationInfo();
    for (const m of info.messages)
      if (m.type === 'error')
        throw new Error('WGSL line ' + m.lineNum + ': ' + m.message);
    bindGroupLayout = device.createBindGroupLayout({entries: [{
      binding: 0, visibility: GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT,
      buffer: {type: 'uniform'}}]});
    layout = device.createPipelineLayout({bindGroupLayouts: [bindGroupLayout]});
    page.adapter = (adapter.info && adapter.info.architecture) || 'unknown';
    page.ready = true;
  };

  // The module's commands for the vector text (written to its file system, read by
  // raster::readGolden there).
  function commandsOf(text) {
    module.FS.writeFile('/vector.json', text);
    const answer = module.ccall('recode_gpu_commands', 'string', ['string'], ['/vector.json']);
    if (answer === null)
      throw new Error(module.ccall('recode_error', 'string', [], []));
    return JSON.parse(answer);
  }

  const align256 = (n) => Math.ceil(n / 256) * 256;

  page.runVector = async function (text) {
    const v = commandsOf(text);
    const w = v.width, h = v.height;
    // Every record of the stream in one vertex buffer; each command draws its range of it.
    const records = [];
    let count = 0;
    const steps = [];
    for (const c of v.commands) {
      const kind = Object.keys(c)[0];
      const s = c[kind];
      const rec = kind === 'draw' ? Uint32Array.from(c.proxies, (x) => x >>> 0)
                : clearRecord(s, kind === 'clear_depth' ? c.q : 0);
      const n = rec.length / RECORD_WORDS;
      const [x0, y0, x1, y1] = s.scissor;
      if (n === 0 || x1 <= x0 || y1 <= y0)
        continue;
      records.push(rec);
      steps.push({kind, s, first: count, n,
                  ref: kind === 'clear_stencil' ? c.value : s.stencil_ref});
      count += n;
    }
    const vertices = device.createBuffer({size: Math.max(count, 1) * RECORD_WORDS * 4,
                                          usage: GPUBufferUsage.VERTEX, mappedAtCreation: true});
    const mapped = new Uint32Array(vertices.getMappedRange());
    let at = 0;
    for (const r of records) {
      mapped.set(r, at);
      at += r.length;
    }
    vertices.unmap();
    const result = {depth_pixels: 0, stencil_pixels: 0, first_difference: null, records: count,
                    gpu_ms: 0, tiles: 0};
    // Tiles of at most the device's largest texture, each replaying the whole stream.
    const size = device.limits.maxTextureDimension2D;
    for (let y0 = 0; y0 < h; y0 += size)
      for (let x0 = 0; x0 < w; x0 += size) {
        await drawTile(v, steps, vertices, [x0, y0, Math.min(x0 + size, w), Math.min(y0 + size, h)],
                       result);
        ++result.tiles;
      }
    vertices.destroy();
    return result;
  };

  // Replays the steps into one tile [x0, x1) x [y0, y1) of the framebuffer, reads it back and
  // adds its differences from the expected buffers to `result`.
  async function drawTile(v, steps, vertices, tile, result) {
    const [tx0, ty0, tx1, ty1] = tile;
    const w = tx1 - tx0, h = ty1 - ty0;
    const uniforms = device.createBuffer({size: 16, usage: GPUBufferUsage.UNIFORM,
                                          mappedAtCreation: true});
    new Float32Array(uniforms.getMappedRange()).set([w, h, tx0, ty0]);
    uniforms.unmap();
    const bindGroup = device.createBindGroup({layout: bindGroupLayout,
                                              entries: [{binding: 0, resource: {buffer: uniforms}}]});
    const target = device.createTexture({size: [w, h], format: FORMAT,
        usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC});

    const t0 = performance.now();
    const encoder = device.createCommandEncoder();
    const pass = encoder.beginRenderPass({colorAttachments: [], depthStencilAttachment: {
      view: target.createView(), depthClearValue: DEPTH_MAX / 16777216, depthLoadOp: 'clear',
      depthStoreOp: 'store', stencilClearValue: 0, stencilLoadOp: 'clear',
      stencilStoreOp: 'store'}});
    pass.setBindGroup(0, bindGroup);
    pass.setVertexBuffer(0, vertices);
    for (const step of steps) {
      // The scissor within the tile; the contract's rows count up from the bottom, the
      // framebuffer's from the top.
      const x0 = Math.max(step.s.scissor[0], tx0), y0 = Math.max(step.s.scissor[1], ty0);
      const x1 = Math.min(step.s.scissor[2], tx1), y1 = Math.min(step.s.scissor[3], ty1);
      if (x1 <= x0 || y1 <= y0)
        continue;
      pass.setPipeline(pipelineFor(step.kind, step.s));
      pass.setScissorRect(x0 - tx0, ty1 - y1, x1 - x0, y1 - y0);
      pass.setStencilReference(step.ref);
      pass.draw(4, step.n, 0, step.first);
    }
    pass.end();
    const depthRow = align256(w * 4), stencilRow = align256(w);
    const depthOut = device.createBuffer({size: depthRow * h,
        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
    const stencilOut = device.createBuffer({size: stencilRow * h,
        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
    encoder.copyTextureToBuffer({texture: target, aspect: 'depth-only'},
                                {buffer: depthOut, bytesPerRow: depthRow}, [w, h]);
    encoder.copyTextureToBuffer({texture: target, aspect: 'stencil-only'},
                                {buffer: stencilOut, bytesPerRow: stencilRow}, [w, h]);
    device.queue.submit([encoder.finish()]);
    await Promise.all([depthOut.mapAsync(GPUMapMode.READ), stencilOut.mapAsync(GPUMapMode.READ)]);
    result.gpu_ms += performance.now() - t0;
    const depth = new Float32Array(depthOut.getMappedRange());
    const stencil = new Uint8Array(stencilOut.getMappedRange());
    const note = (x, y, buffer, expected, got) => {
      result.first_difference = result.first_difference || {x, y, buffer, expected, got};
    };
    for (let j = ty0; j < ty1; ++j) {
      const r = ty1 - 1 - j;
      for (let i = tx0; i < tx1; ++i) {
        const at = j * v.width + i;
        const d = depth[r * depthRow / 4 + (i - tx0)] * 16777216;
        if (d !== v.depth[at]) {  // q 2^-24 is exact in a float: anything else differs
          ++result.depth_pixels;
          note(i, j, 'depth', v.depth[at], d);
        }
        const st = stencil[r * stencilRow + (i - tx0)];
        if (st !== v.stencil[at]) {
          ++result.stencil_pixels;
          note(i, j, 'stencil', v.stencil[at], st);
        }
      }
    }
    depthOut.unmap();
    stencilOut.unmap();
    for (const b of [depthOut, stencilOut, uniforms])
      b.destroy();
    target.destroy();
  }
})();
