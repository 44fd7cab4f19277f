#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// Stage 5 of the compute device's tile rasterizer: one workgroup an 8x8 block of the scissor's
// grid, one invocation a pixel. Every invocation runs its pixel's fragments in the order of the
// block's list (sorted by tile_sort.comp), keeping its depth and stencil in registers: coverage and the fill rule (section 4 of
// docs/rasterization.md), depth and its quantisation (5), the stencil test, the depth test, the
// face's ops and the write masks (6). Pixels outside the scissor take no part.

layout(local_size_x = 8, local_size_y = 8) in;

#include "exact_contract.glsl"
#include "tile_common.glsl"

// The set-up triangles (tile_common.glsl's layout) read four words at a time.
layout(std430, set = 0, binding = 2) readonly buffer Triangles { uvec4 triangles[]; };
layout(std430, set = 0, binding = 3) readonly buffer BlockCounts { uint blockCounts[]; };
layout(std430, set = 0, binding = 4) readonly buffer BlockOffsets { uint blockOffsets[]; };
layout(std430, set = 0, binding = 6) readonly buffer Pairs { uint pairs[]; };
layout(std430, set = 0, binding = 7) buffer Framebuffer { uint pixels[]; };

bool compare(uint func, uint incoming, uint stored) {
  switch (func) {
    case 0u: return false;                // NEVER
    case 1u: return incoming < stored;    // LESS
    case 2u: return incoming == stored;   // EQUAL
    case 3u: return incoming <= stored;   // LEQUAL
    case 4u: return incoming > stored;    // GREATER
    case 5u: return incoming != stored;   // NOTEQUAL
    case 6u: return incoming >= stored;   // GEQUAL
    default: return true;                 // ALWAYS
  }
}

uint applyStencilOp(uint op, uint s, uint ref) {
  switch (op) {
    case 0u: return s;                       // KEEP
    case 1u: return 0u;                      // ZERO
    case 2u: return ref;                     // REPLACE
    case 3u: return min(s + 1u, 255u);       // INCR
    case 4u: return (s + 1u) & 0xFFu;        // INCR_WRAP
    case 5u: return s == 0u ? 0u : s - 1u;   // DECR
    case 6u: return (s + 255u) & 0xFFu;      // DECR_WRAP
    default: return 255u - s;                // INVERT
  }
}

// This invocation's pixel, and its depth and stencil while the block is drawn.
ivec2 pixel;
bool inside;
uint depth;
uint stencil;

// Triangle t's fragment at this pixel, if it covers its centre.
void shade(uint t) {
  const uvec4 rectWords = triangles[4u * t + 1u];  // X2, Y2, front, x0
  const uvec4 moreWords = triangles[4u * t + 2u];  // y0, x1, y1, z0
  if (pixel.x < int(rectWords.w) || pixel.y < int(moreWords.x) || pixel.x >= int(moreWords.y) ||
      pixel.y >= int(moreWords.z))
    return;  // also every pixel outside the scissor, and every triangle that draws nothing
  const uvec4 vertexWords = triangles[4u * t];  // X0, Y0, X1, Y1
  const i64vec2 v0 = i64vec2(ivec2(vertexWords.xy));
  const i64vec2 v1 = i64vec2(ivec2(vertexWords.zw));
  const i64vec2 v2 = i64vec2(ivec2(rectWords.xy));
  const bool front = rectWords.z != 0u;
  const i64vec2 centre = i64vec2(pixel) * 256l + 128l;
  if (!triangleCovers(v0, v1, v2, front, centre))
    return;
  const uint ref = draw.stencil & 0xFFu;
  const uint valueMask = (draw.stencil >> 8) & 0xFFu;
  const uint writeMask = (draw.stencil >> 16) & 0xFFu;
  const uint ops = front ? (draw.ops & 0x1FFu) : ((draw.ops >> 9) & 0x1FFu);
  uint op;
  if (!compare((draw.tests >> 4) & 7u, ref & valueMask, stencil & valueMask)) {
    op = ops & 7u;  // stencil fail
  } else {
    const double z0 = double(uintBitsToFloat(moreWords.w));
    const uvec4 slopeWords = triangles[4u * t + 3u];
    const dvec2 slopes =
        dvec2(packDouble2x32(slopeWords.xy), packDouble2x32(slopeWords.zw));
    const uint q = quantizeDepth(depthAt(z0, slopes, v0, centre));
    if (!compare(draw.tests & 7u, q, depth)) {
      op = (ops >> 3) & 7u;  // depth fail
    } else {
      op = (ops >> 6) & 7u;  // depth pass
      if ((draw.tests & 8u) != 0u)
        depth = q;
    }
  }
  const uint next = applyStencilOp(op, stencil, ref);
  stencil = (next & writeMask) | (stencil & ~writeMask & 0xFFu);
}

// Draws block (bx, by) of the scissor's grid: this invocation's pixel of it.
void drawBlock(uint bx, uint by) {
  const uint block = by * draw.gridWidth + bx;
  pixel = ivec2((draw.scissor.x & ~7) + int(bx * 8u + gl_LocalInvocationID.x),
                (draw.scissor.y & ~7) + int(by * 8u + gl_LocalInvocationID.y));
  inside = pixel.x >= draw.scissor.x && pixel.y >= draw.scissor.y && pixel.x < draw.scissor.z &&
           pixel.y < draw.scissor.w;
  const uint count = blockCounts[block];
  if (count == 0u)
    return;
  const uint at = uint(pixel.y) * draw.width + uint(pixel.x);
  const uint before = inside ? pixels[at] : 0u;
  depth = depthOf(before);
  stencil = stencilOf(before);
  const uint offset = blockOffsets[block];
  if (offset + count > draw.pairCapacity) {
    // The list did not fit: every triangle of the draw, in index order (a set-up triangle that
    // misses this pixel is skipped by its candidate rectangle).
    for (uint t = 0u; t < draw.triangleCount; ++t)
      shade(t);
  } else {
    for (uint k = 0u; k < count; ++k)  // sorted by tile_sort.comp
      shade(pairs[offset + k]);
  }
  if (inside)
    pixels[at] = packPixel(depth, stencil);
}

// A workgroup draws blocksPerGroup consecutive blocks of a row of the grid, one after the other:
// one on a GPU, several on a CPU driver, where a workgroup's fixed cost is high.
void main() {
  const uint first = gl_WorkGroupID.x * draw.blocksPerGroup;
  const uint end = min(first + draw.blocksPerGroup, draw.gridWidth);
  for (uint bx = first; bx < end; ++bx)
    drawBlock(bx, gl_WorkGroupID.y);
}
