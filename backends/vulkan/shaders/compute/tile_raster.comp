#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// Stage 4 of the compute device's tile rasterizer: one workgroup an 8x8 block of the scissor's
// grid, one invocation a pixel. The block's list (tile_scatter.comp) is sorted by triangle index
// in shared memory, then every invocation runs its pixel's fragments in that order, keeping its
// depth and stencil in registers: coverage and the fill rule (section 4 of
// docs/rasterization.md), depth and its quantisation (5), the stencil test, the depth test, the
// face's ops and the write masks (6). Pixels outside the scissor take no part.

layout(local_size_x = 8, local_size_y = 8) in;

#include "exact_contract.glsl"
#include "tile_common.glsl"

layout(std430, set = 0, binding = 2) readonly buffer Triangles { uint triangles[]; };
layout(std430, set = 0, binding = 3) readonly buffer BlockCounts { uint blockCounts[]; };
layout(std430, set = 0, binding = 4) readonly buffer BlockOffsets { uint blockOffsets[]; };
layout(std430, set = 0, binding = 6) readonly buffer Pairs { uint pairs[]; };
layout(std430, set = 0, binding = 7) buffer Framebuffer { uint pixels[]; };

// Lists of up to kSorted entries are sorted whole; longer ones in windows of kSorted indices.
const uint kSorted = 1024u;
const uint kNoTriangle = 0xFFFFFFFFu;
shared uint list[kSorted];
shared uint listSize;
shared uint windowStart;

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
  const uint base = t * kWordsPerTriangle;
  if (pixel.x < int(triangles[base + 7u]) || pixel.y < int(triangles[base + 8u]) ||
      pixel.x >= int(triangles[base + 9u]) || pixel.y >= int(triangles[base + 10u]))
    return;  // also every pixel outside the scissor, and every triangle that draws nothing
  const i64vec2 v0 = i64vec2(int(triangles[base + 0u]), int(triangles[base + 1u]));
  const i64vec2 v1 = i64vec2(int(triangles[base + 2u]), int(triangles[base + 3u]));
  const i64vec2 v2 = i64vec2(int(triangles[base + 4u]), int(triangles[base + 5u]));
  const bool front = triangles[base + 6u] != 0u;
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
    const double z0 = double(uintBitsToFloat(triangles[base + 11u]));
    const dvec2 slopes = dvec2(packDouble2x32(uvec2(triangles[base + 12u], triangles[base + 13u])),
                               packDouble2x32(uvec2(triangles[base + 14u], triangles[base + 15u])));
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

// Sorts list[0, n) ascending (bitonic, padded to a power of two with kNoTriangle).
void sortList(uint n) {
  uint size = 1u;
  while (size < n)
    size <<= 1u;
  const uint lane = gl_LocalInvocationIndex;
  for (uint k = n + lane; k < size; k += 64u)
    list[k] = kNoTriangle;
  barrier();
  for (uint run = 2u; run <= size; run <<= 1u) {
    for (uint stride = run >> 1u; stride > 0u; stride >>= 1u) {
      for (uint k = lane; k < size; k += 64u) {
        const uint partner = k ^ stride;
        if (partner > k) {
          const bool ascending = (k & run) == 0u;
          const uint a = list[k];
          const uint b = list[partner];
          if ((a > b) == ascending) {
            list[k] = b;
            list[partner] = a;
          }
        }
      }
      barrier();
    }
  }
}

void main() {
  const uint block = gl_WorkGroupID.y * draw.gridWidth + gl_WorkGroupID.x;
  pixel = ivec2((draw.scissor.x & ~7) + int(gl_WorkGroupID.x * 8u + gl_LocalInvocationID.x),
                (draw.scissor.y & ~7) + int(gl_WorkGroupID.y * 8u + gl_LocalInvocationID.y));
  inside = pixel.x >= draw.scissor.x && pixel.y >= draw.scissor.y && pixel.x < draw.scissor.z &&
           pixel.y < draw.scissor.w;
  const uint at = uint(pixel.y) * draw.width + uint(pixel.x);
  const uint before = inside ? pixels[at] : 0u;
  depth = depthOf(before);
  stencil = stencilOf(before);
  const uint count = blockCounts[block];
  const uint offset = blockOffsets[block];
  const uint lane = gl_LocalInvocationIndex;
  if (count == 0u)
    return;
  if (offset + count > draw.pairCapacity) {
    // The list did not fit: every triangle of the draw, in index order (a set-up triangle that
    // misses this pixel is skipped by its candidate rectangle).
    for (uint t = 0u; t < draw.triangleCount; ++t)
      shade(t);
  } else if (count <= kSorted) {
    for (uint k = lane; k < count; k += 64u)
      list[k] = pairs[offset + k];
    sortList(count);
    for (uint k = 0u; k < count; ++k)
      shade(list[k]);
  } else {
    // Windows of kSorted consecutive triangle indices, each starting at the smallest index not
    // drawn yet: a window holds at most kSorted of the list's distinct indices.
    uint from = 0u;
    for (;;) {
      if (lane == 0u) {
        windowStart = kNoTriangle;
        listSize = 0u;
      }
      barrier();
      for (uint k = lane; k < count; k += 64u) {
        const uint t = pairs[offset + k];
        if (t >= from)
          atomicMin(windowStart, t);
      }
      barrier();
      const uint start = windowStart;
      if (start == kNoTriangle)
        break;
      for (uint k = lane; k < count; k += 64u) {
        const uint t = pairs[offset + k];
        if (t >= start && t - start < kSorted)
          list[atomicAdd(listSize, 1u)] = t;
      }
      barrier();
      const uint n = listSize;
      sortList(n);
      for (uint k = 0u; k < n; ++k)
        shade(list[k]);
      from = start + kSorted;
      barrier();
    }
  }
  if (inside)
    pixels[at] = packPixel(depth, stencil);
}
