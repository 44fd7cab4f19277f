// The stages of the WebGPU back end, appended to exact_contract32.wgsl (WGSL has no include):
// exact32_vk.vert and exact32_vk.frag of the Vulkan device without 64-bit arithmetic, in WGSL.
// Each proxy record (backends::ProxyTriangle, 72 bytes, per instance) is drawn as a rectangle
// over its candidate pixels; the fragment stage decides coverage and depth at the pixel centre
// exactly as the contract does and writes q 2^-24, which a depth32float attachment holds
// exactly. z arrives as the floats' bits, so no float operation touches it.
//
// WebGPU's clip space has y up like GL's window coordinates, so a corner's pixel position maps
// to clip space without a flip; its framebuffer rows run top down, so the contract's row j is
// height - 1 - r (the fragment stage turns position back into GL window coordinates).
//
// A framebuffer larger than the device's largest texture is drawn in tiles (the contract allows
// 16384 pixels a side, WebGPU guarantees 8192): the attachment is the tile whose lower-left
// pixel is `origin` in the contract's coordinates, so positions are shifted by it on the way in
// and back on the way out; the records keep the whole framebuffer's coordinates.

struct Frame {
  framebufferSize: vec2<f32>,  // the tile's
  origin: vec2<f32>,           // the tile's lower-left pixel, in the contract's coordinates
}

@group(0) @binding(0) var<uniform> frame: Frame;

struct Proxy {
  @location(0) pixelRect: vec4<i32>,  // proxy [x0, x1) x [y0, y1) in pixels
  @location(1) fixedV0V1: vec4<i32>,  // snapped (X0, Y0, X1, Y1), 24.8 fixed point
  @location(2) fixedV2: vec2<i32>,    // snapped (X2, Y2)
  @location(3) vertexZ: vec3<u32>,    // the bits of z0, z1, z2 as submitted
  @location(4) frontFacing: i32,      // sign of the snapped area: 1 front, 0 back
  @location(5) slopeBits: vec4<u32>,  // dzdx, dzdy as set up on the CPU, low words first
}

struct Triangle {
  @builtin(position) position: vec4<f32>,
  @location(0) @interpolate(flat) triV0V1: vec4<i32>,
  @location(1) @interpolate(flat) triV2: vec2<i32>,
  @location(2) @interpolate(flat) triFront: i32,
  @location(3) @interpolate(flat) planeZ0: vec2<u32>,      // (double) z0's bits
  @location(4) @interpolate(flat) planeSlopes: vec4<u32>,  // dzdx, dzdy's bits
}

// The rectangle's corner for a 4-vertex strip that winds counter-clockwise, mirrored in x for
// a back-facing triangle so that the proxy takes the back stencil ops (exact32_vk.vert).
fn proxyCorner(pixelRect: vec4<i32>, frontFacing: i32, vertexIndex: u32) -> vec4<f32> {
  var right = (vertexIndex & 1u) != 0u;
  let top = (vertexIndex & 2u) != 0u;
  if (frontFacing == 0) {
    right = !right;
  }
  let corner = vec2<f32>(f32(select(pixelRect.x, pixelRect.z, right)),
                         f32(select(pixelRect.y, pixelRect.w, top)));
  return vec4<f32>((corner - frame.origin) / frame.framebufferSize * 2.0 - 1.0, 0.0, 1.0);
}

@vertex
fn proxyVertex(p: Proxy, @builtin(vertex_index) vertexIndex: u32) -> Triangle {
  var t: Triangle;
  t.position = proxyCorner(p.pixelRect, p.frontFacing, vertexIndex);
  t.triV0V1 = p.fixedV0V1;
  t.triV2 = p.fixedV2;
  t.triFront = p.frontFacing;
  t.planeZ0 = doubleFromFloatBits(p.vertexZ.x);
  t.planeSlopes = p.slopeBits;
  return t;
}

// The contract's window coordinates of the fragment at framebuffer position fragCoord (rows
// from the top of the tile).
fn glWindow(fragCoord: vec4<f32>) -> vec2<f32> {
  return frame.origin + vec2<f32>(fragCoord.x, frame.framebufferSize.y - fragCoord.y);
}

@fragment
fn proxyFragment(t: Triangle) -> @builtin(frag_depth) f32 {
  let centre = pixelCentreFixed32(glWindow(t.position));
  let v0 = t.triV0V1.xy;
  if (!triangleCovers32(v0, t.triV0V1.zw, t.triV2, t.triFront != 0, centre)) {
    discard;
  }
  let q = quantizeDepth32(depthAt32(t.planeZ0, t.planeSlopes, v0, centre));
  return f32(q) * (1.0 / 16777216.0);
}

// Clears are drawn as a rectangle over the scissor (a record whose pixelRect is the scissor and
// whose z0 holds the bits of q 2^-24), so that they honour the scissor and the write masks the
// way the reference does; a load op would clear the whole attachment.
struct Clear {
  @builtin(position) position: vec4<f32>,
  @location(0) @interpolate(flat) depthBits: u32,
}

@vertex
fn clearVertex(p: Proxy, @builtin(vertex_index) vertexIndex: u32) -> Clear {
  var c: Clear;
  c.position = proxyCorner(p.pixelRect, 1, vertexIndex);
  c.depthBits = p.vertexZ.x;
  return c;
}

@fragment
fn clearFragment(c: Clear) -> @builtin(frag_depth) f32 {
  return bitcast<f32>(c.depthBits);
}
