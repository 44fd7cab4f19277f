#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// Stage 1 of the compute device's tile rasterizer: triangle set-up, one invocation a triangle.
// Snaps the three window vertices (section 2 of docs/rasterization.md), takes the doubled area,
// the facing and the culling (section 3), clips the candidate pixels to the scissor and sets up
// the depth plane (section 5, exact_contract.glsl: every operation `precise`, the division
// correctly rounded); then counts the triangle once in each 8x8 block its candidates reach where
// it may cover a centre (tile_block_test.glsl).

layout(local_size_x = 64) in;

#include "exact_contract.glsl"
#include "tile_common.glsl"
#include "tile_block_test.glsl"

layout(std430, set = 0, binding = 0) readonly buffer Vertices { float vertexData[]; };
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indexData[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Triangles { uint triangles[]; };
layout(std430, set = 0, binding = 3) buffer BlockCounts { uint blockCounts[]; };

// The snapped position of vertex v: nearbyint(x 256), in double, round half to even.
i64vec2 snapped(uint v) {
  precise double x = double(vertexData[3u * v]) * 256.0;
  precise double y = double(vertexData[3u * v + 1u]) * 256.0;
  return i64vec2(roundToNearestEven(x), roundToNearestEven(y));
}

void writeEmpty(uint base) {
  triangles[base + 7u] = 0u;
  triangles[base + 8u] = 0u;
  triangles[base + 9u] = 0u;
  triangles[base + 10u] = 0u;
}

void main() {
  const uint t = linearInvocation();
  if (t >= draw.triangleCount)
    return;
  const uint base = t * kWordsPerTriangle;
  const uint i0 = indexData[3u * t];
  const uint i1 = indexData[3u * t + 1u];
  const uint i2 = indexData[3u * t + 2u];
  const i64vec2 v0 = snapped(i0);
  const i64vec2 v1 = snapped(i1);
  const i64vec2 v2 = snapped(i2);
  const int64_t area = twiceArea(v0, v1, v2);
  const bool front = area > 0l;
  const uint cull = (draw.tests >> 7) & 3u;  // CullMode: none, front, back
  if (area == 0l || (cull == 1u && front) || (cull == 2u && !front)) {
    writeEmpty(base);
    return;
  }
  // Pixels whose centres (256 i + 128) lie in the snapped bounding box, then the scissor.
  const int64_t minX = min(v0.x, min(v1.x, v2.x));
  const int64_t maxX = max(v0.x, max(v1.x, v2.x));
  const int64_t minY = min(v0.y, min(v1.y, v2.y));
  const int64_t maxY = max(v0.y, max(v1.y, v2.y));
  const int x0 = max(int((minX + 127l) >> 8), draw.scissor.x);
  const int x1 = min(int(((maxX - 128l) >> 8) + 1l), draw.scissor.z);
  const int y0 = max(int((minY + 127l) >> 8), draw.scissor.y);
  const int y1 = min(int(((maxY - 128l) >> 8) + 1l), draw.scissor.w);
  if (x0 >= x1 || y0 >= y1) {
    writeEmpty(base);
    return;
  }
  triangles[base + 0u] = uint(int(v0.x));
  triangles[base + 1u] = uint(int(v0.y));
  triangles[base + 2u] = uint(int(v1.x));
  triangles[base + 3u] = uint(int(v1.y));
  triangles[base + 4u] = uint(int(v2.x));
  triangles[base + 5u] = uint(int(v2.y));
  triangles[base + 6u] = front ? 1u : 0u;
  triangles[base + 7u] = uint(x0);
  triangles[base + 8u] = uint(y0);
  triangles[base + 9u] = uint(x1);
  triangles[base + 10u] = uint(y1);
  const vec3 z = vec3(vertexData[3u * i0 + 2u], vertexData[3u * i1 + 2u], vertexData[3u * i2 + 2u]);
  const dvec2 slopes = depthSlopes(v0, v1, v2, z);
  triangles[base + 11u] = floatBitsToUint(z.x);
  const uvec2 dzdx = unpackDouble2x32(slopes.x);
  const uvec2 dzdy = unpackDouble2x32(slopes.y);
  triangles[base + 12u] = dzdx.x;
  triangles[base + 13u] = dzdx.y;
  triangles[base + 14u] = dzdy.x;
  triangles[base + 15u] = dzdy.y;
  const uvec2 first = blockOf(x0, y0);
  const uvec2 last = blockOf(x1 - 1, y1 - 1);
  const i64vec2 p1 = front ? v1 : v2;
  const i64vec2 p2 = front ? v2 : v1;
  for (uint by = first.y; by <= last.y; ++by)
    for (uint bx = first.x; bx <= last.x; ++bx)
      if (blockMeetsTriangle(v0, p1, p2, uvec2(bx, by)))
        atomicAdd(blockCounts[by * draw.gridWidth + bx], 1u);
}
