#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// Stage 5 of the compute device's tile rasterizer: the fragments of each 8x8 block of the
// scissor's grid, in the order of the block's list (sorted by tile_sort.comp). Eight invocations
// draw a block, one a column of its pixels, keeping the column's eight depths and stencils in
// registers; a workgroup of 64 draws eight blocks side by side (and, on a CPU driver, more along
// the row: Draw.blocksPerGroup). Per triangle, an invocation works out its column's part once
// and steps down the rows the triangle's candidates reach, with the same operations in the same
// order as section 5 and 7 of docs/rasterization.md:
//   coverage: each edge function E = dx (Yc - Ya) - dy (Xc - Xa) at the first row, then plus
//   256 dx a row (exact 64-bit integers), covered when E > 0 or E = 0 on an inclusive edge (4);
//   depth: z = (z0 + tx) + ty with tx = dzdx (Xc - X0) for the column and ty = dzdy (Yc - Y0)
//   for the row, each rounded on its own, then quantised (5);
//   then the stencil test, the depth test, the face's ops and the write masks (6).

layout(local_size_x = 64) in;

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

// This invocation's column of the block being drawn: its x, its first row, and the eight
// pixels' depth and stencil.
int column;
int firstRow;
uint depth[8];
uint stencil[8];

// The edge a -> b of a counter-clockwise triangle at the centre (xc, yc): E minus the fill
// rule's bias (0 on an inclusive edge, 1 on another), so that a centre is covered when the
// value is >= 0; and its step from one row to the next.
int64_t biasedEdge(i64vec2 a, i64vec2 b, int64_t xc, int64_t yc) {
  const int64_t dx = b.x - a.x;
  const int64_t dy = b.y - a.y;
  const int64_t bias = (dy < 0l || (dy == 0l && dx > 0l)) ? 0l : 1l;
  return dx * (yc - a.y) - dy * (xc - a.x) - bias;
}

// Triangle t's fragments in this column.
void shade(uint t) {
  const uvec4 rectWords = triangles[4u * t + 1u];  // X2, Y2, front, x0
  const uvec4 moreWords = triangles[4u * t + 2u];  // y0, x1, y1, z0
  // Its candidate rows in this block (the candidates lie inside the scissor).
  const int rowStart = max(int(moreWords.x), firstRow);
  const int rowEnd = min(int(moreWords.z), firstRow + 8);
  if (rowStart >= rowEnd || column < int(rectWords.w) || column >= int(moreWords.y))
    return;
  const uvec4 vertexWords = triangles[4u * t];  // X0, Y0, X1, Y1
  const i64vec2 v0 = i64vec2(ivec2(vertexWords.xy));
  const i64vec2 v1 = i64vec2(ivec2(vertexWords.zw));
  const i64vec2 v2 = i64vec2(ivec2(rectWords.xy));
  const bool front = rectWords.z != 0u;
  // Counter-clockwise: (v0, v1, v2) when front-facing, (v0, v2, v1) when back-facing.
  const i64vec2 p1 = front ? v1 : v2;
  const i64vec2 p2 = front ? v2 : v1;
  const int64_t xc = int64_t(column) * 256l + 128l;
  const int64_t yc = int64_t(rowStart) * 256l + 128l;
  int64_t e0 = biasedEdge(v0, p1, xc, yc);
  int64_t e1 = biasedEdge(p1, p2, xc, yc);
  int64_t e2 = biasedEdge(p2, v0, xc, yc);
  const int64_t step0 = (p1.x - v0.x) * 256l;
  const int64_t step1 = (p2.x - p1.x) * 256l;
  const int64_t step2 = (v0.x - p2.x) * 256l;
  const double z0 = double(uintBitsToFloat(moreWords.w));
  const uvec4 slopeWords = triangles[4u * t + 3u];
  const double dzdx = packDouble2x32(slopeWords.xy);
  const double dzdy = packDouble2x32(slopeWords.zw);
  precise double tx = dzdx * double(xc - v0.x);
  precise double zx = z0 + tx;  // the plane's column part, as CpuDevice keeps it per block
  const uint ref = draw.stencil & 0xFFu;
  const uint valueMask = (draw.stencil >> 8) & 0xFFu;
  const uint writeMask = (draw.stencil >> 16) & 0xFFu;
  const uint ops = front ? (draw.ops & 0x1FFu) : ((draw.ops >> 9) & 0x1FFu);
  const uint depthFunc = draw.tests & 7u;
  const uint stencilFunc = (draw.tests >> 4) & 7u;
  const bool depthWrite = (draw.tests & 8u) != 0u;
  for (int row = rowStart; row < rowEnd; ++row) {
    if (e0 >= 0l && e1 >= 0l && e2 >= 0l) {
      const int k = row - firstRow;
      const uint s = stencil[k];
      uint op;
      if (!compare(stencilFunc, ref & valueMask, s & valueMask)) {
        op = ops & 7u;  // stencil fail
      } else {
        precise double ty = dzdy * double(int64_t(row) * 256l + 128l - v0.y);
        precise double z = zx + ty;
        const uint q = quantizeDepth(z);
        if (!compare(depthFunc, q, depth[k])) {
          op = (ops >> 3) & 7u;  // depth fail
        } else {
          op = (ops >> 6) & 7u;  // depth pass
          if (depthWrite)
            depth[k] = q;
        }
      }
      const uint next = applyStencilOp(op, s, ref);
      stencil[k] = (next & writeMask) | (s & ~writeMask & 0xFFu);
    }
    e0 += step0;
    e1 += step1;
    e2 += step2;
  }
}

// Draws block (bx, by) of the scissor's grid: this invocation's column of it.
void drawBlock(uint bx, uint by) {
  const uint block = by * draw.gridWidth + bx;
  const uint count = blockCounts[block];
  if (count == 0u)
    return;
  column = (draw.scissor.x & ~7) + int(bx * 8u) + int(gl_LocalInvocationID.x & 7u);
  firstRow = (draw.scissor.y & ~7) + int(by * 8u);
  // Pixels outside the scissor are read and written back unchanged (no candidate reaches them).
  const bool inColumn = column >= draw.scissor.x && column < draw.scissor.z;
  for (int k = 0; k < 8; ++k) {
    const int row = firstRow + k;
    const bool inside = inColumn && row >= draw.scissor.y && row < draw.scissor.w;
    const uint word = inside ? pixels[uint(row) * draw.width + uint(column)] : 0u;
    depth[k] = depthOf(word);
    stencil[k] = stencilOf(word);
  }
  const uint offset = blockOffsets[block];
  if (offset + count > draw.pairCapacity) {
    // The list did not fit: every triangle of the draw, in index order (a set-up triangle that
    // misses this column is skipped by its candidate rectangle).
    for (uint t = 0u; t < draw.triangleCount; ++t)
      shade(t);
  } else {
    for (uint k = 0u; k < count; ++k)
      shade(pairs[offset + k]);
  }
  for (int k = 0; k < 8; ++k) {
    const int row = firstRow + k;
    if (inColumn && row >= draw.scissor.y && row < draw.scissor.w)
      pixels[uint(row) * draw.width + uint(column)] = packPixel(depth[k], stencil[k]);
  }
}

// Invocation i draws column i % 8 of every eighth block of the workgroup's span of the row,
// from block i / 8 on: eight blocks side by side, and Draw.blocksPerGroup blocks in all.
void main() {
  const uint span = draw.blocksPerGroup;
  const uint first = gl_WorkGroupID.x * span;
  const uint end = min(first + span, draw.gridWidth);
  for (uint bx = first + (gl_LocalInvocationID.x >> 3); bx < end; bx += 8u)
    drawBlock(bx, gl_WorkGroupID.y);
}
