#version 450
#extension GL_GOOGLE_include_directive : require
// Stage 3 of the compute device's tile rasterizer: binning. Each triangle writes its index into
// the list of every 8x8 block its candidate pixels reach. The slots come from atomic cursors, so
// a block's list holds its triangles in no particular order; the raster stage sorts each list
// by index before drawing it. Entries past the list's capacity are dropped, and a block whose
// list did not fit is drawn from every triangle of the draw instead (tile_raster.comp).

layout(local_size_x = 64) in;

#include "tile_common.glsl"

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
  const uvec2 first = blockOf(x0, y0);
  const uvec2 last = blockOf(x1 - 1, y1 - 1);
  for (uint by = first.y; by <= last.y; ++by) {
    for (uint bx = first.x; bx <= last.x; ++bx) {
      const uint slot = atomicAdd(blockCursors[by * draw.gridWidth + bx], 1u);
      if (slot < draw.pairCapacity)
        pairs[slot] = t;
    }
  }
}
