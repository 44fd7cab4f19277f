#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// Stage 3 of the compute device's tile rasterizer: binning. Each triangle writes its index into
// the list of every 8x8 block its candidate pixels reach where it may cover a centre (the
// set-up's test, tile_block_test.glsl, so the lists have the lengths it counted). The slots come from atomic cursors, so
// a block's list holds its triangles in no particular order; the next stage (tile_sort.comp)
// sorts each list by index. Entries past the list's capacity are dropped, and a block whose
// list did not fit is drawn from every triangle of the draw instead (tile_raster.comp).

layout(local_size_x = 64) in;

#include "tile_common.glsl"
#include "tile_block_test.glsl"

layout(std430, set = 0, binding = 2) readonly buffer Triangles { uint triangles[]; };
layout(std430, set = 0, binding = 5) buffer BlockCursors { uint blockCursors[]; };
layout(std430, set = 0, binding = 6) writeonly buffer Pairs { uint pairs[]; };

void main() {
  const uint t = linearInvocation();
  if (t >= draw.triangleCount)
    return;
  const uint base = t * kWordsPerTriangle;
  const int x0 = int(triangles[base + 7u]);
  const int y0 = int(triangles[base + 8u]);
  const int x1 = int(triangles[base + 9u]);
  const int y1 = int(triangles[base + 10u]);
  if (x0 >= x1 || y0 >= y1)
    return;
  const i64vec2 v0 = i64vec2(int(triangles[base + 0u]), int(triangles[base + 1u]));
  const i64vec2 v1 = i64vec2(int(triangles[base + 2u]), int(triangles[base + 3u]));
  const i64vec2 v2 = i64vec2(int(triangles[base + 4u]), int(triangles[base + 5u]));
  const bool front = triangles[base + 6u] != 0u;
  const i64vec2 p1 = front ? v1 : v2;
  const i64vec2 p2 = front ? v2 : v1;
  const uvec2 first = blockOf(x0, y0);
  const uvec2 last = blockOf(x1 - 1, y1 - 1);
  for (uint by = first.y; by <= last.y; ++by) {
    for (uint bx = first.x; bx <= last.x; ++bx) {
      if (!blockMeetsTriangle(v0, p1, p2, uvec2(bx, by)))
        continue;
      const uint slot = atomicAdd(blockCursors[by * draw.gridWidth + bx], 1u);
      if (slot < draw.pairCapacity)
        pairs[slot] = t;
    }
  }
}
