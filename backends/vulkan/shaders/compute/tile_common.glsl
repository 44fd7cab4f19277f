// What every stage of the vulkan-compute device's tile rasterizer shares (docs/backends.md,
// "The compute device"): the draw's parameters, the layout of a set-up triangle, and the
// framebuffer's packing. Included after the stage's #version and extensions.
//
// The framebuffer is one 32-bit word a pixel, rows from the bottom (GL window order): the
// contract's 24-bit depth q in the high bits and the 8-bit stencil in the low byte.

layout(push_constant) uniform Draw {
  ivec4 scissor;       // x0, y0, x1, y1: the state's scissor, clamped to the framebuffer
  uint width;          // framebuffer width in pixels
  uint height;         // framebuffer height in pixels
  uint triangleCount;  // triangles of the draw; for a clear, its value; for a read, its mode
  uint tests;          // depth func (bits 0-2), depth write (3), stencil func (4-6), cull (7-8)
  uint stencil;        // ref (bits 0-7), value mask (8-15), write mask (16-23)
  uint ops;            // front sfail, dpfail, dppass (3 bits each), then back's, from bit 9
  uint gridWidth;      // 8x8 blocks per row of the scissor's grid
  uint gridHeight;     // rows of blocks
  uint pairCapacity;   // entries the bins' list holds
  uint outWord;        // a read's first word in its output
  uint blocksPerGroup; // the raster stage's blocks a workgroup, along a row of the grid
} draw;

const uint kWordsPerTriangle = 16u;
// A set-up triangle's words (Triangles[]):
//  0-5   snapped X0, Y0, X1, Y1, X2, Y2 (24.8 fixed point, |value| <= 2^23) as int bits
//  6     1 front-facing, 0 back-facing
//  7-10  candidate pixels inside the scissor, half-open x0, y0, x1, y1 (empty: draws nothing)
//  11    z0's float bits
//  12-13 dzdx's double bits, low word first; 14-15 dzdy's

// The 8x8 block of the scissor's grid that holds pixel (x, y) (x, y inside the scissor).
uvec2 blockOf(int x, int y) {
  return uvec2(uint(x - (draw.scissor.x & ~7)) >> 3, uint(y - (draw.scissor.y & ~7)) >> 3);
}

uint packPixel(uint q, uint s) {
  return (q << 8) | (s & 0xFFu);
}

uint depthOf(uint word) {
  return word >> 8;
}

uint stencilOf(uint word) {
  return word & 0xFFu;
}

// The invocation's index in a one-dimensional dispatch of 64-wide workgroups that the host
// spread over rows of at most 65535 workgroups (the smallest limit a device may have).
uint linearInvocation() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u +
         gl_LocalInvocationID.x;
}
