#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's binning, run twice around the scan (Frame.binPass): each triangle finds every job
// (a block of its epoch's grid) its candidate pixels reach where it may cover a centre
// (tile_block_test.glsl); the first pass counts it in each, the second writes its frame index
// into each job's list, at slots from atomic cursors, so a list holds its triangles in no
// particular order; the next stage (tile_sort.comp) sorts each list by index, which is command
// order. Entries past the lists' capacity are dropped, and a job whose list did not fit draws
// each of its draws from every triangle instead (tile_raster.comp).
//
// A triangle's candidate blocks, row by row, are cut into Frame.scatterChunks chunks of
// Frame.scatterBlocks, one invocation a chunk (one chunk of them all on a GPU), so that no
// invocation's loop passes a CPU driver's limit (tile_frame_budgets.hpp). An invocation whose loop
// ended before its chunk's end counts itself in Counters, which the host checks.

layout(local_size_x = 64) in;

#include "tile_common.glsl"
#include "tile_frame_inputs.glsl"
#include "tile_block_test.glsl"

layout(std430, set = 0, binding = 6) readonly buffer Triangles { SetUpTriangle triangles[]; };
layout(std430, set = 0, binding = 7) buffer BinEntries { uint binEntries[]; };
layout(std430, set = 0, binding = 9) buffer BinCursors { uint binCursors[]; };
layout(std430, set = 0, binding = 10) writeonly buffer Lists { uint lists[]; };
layout(std430, set = 0, binding = 19) buffer Counters { uint counters[]; };

void main() {
  const uint invocation = linearInvocation();
  const uint t = invocation / frame.scatterChunks;
  const uint chunk = invocation % frame.scatterChunks;
  if (t >= frame.triangleCount)
    return;
  const int x0 = triangles[t].candidates[0];
  const int y0 = triangles[t].candidates[1];
  const int x1 = triangles[t].candidates[2];
  const int y1 = triangles[t].candidates[3];
  if (x0 >= x1 || y0 >= y1)
    return;
  const Epoch epoch = epochs[draws[drawOfTriangle(t)].epoch];
  const i64vec2 v0 = i64vec2(triangles[t].x0, triangles[t].y0);
  const i64vec2 v1 = i64vec2(triangles[t].x1, triangles[t].y1);
  const i64vec2 v2 = i64vec2(triangles[t].x2, triangles[t].y2);
  const bool front = triangles[t].front != 0u;
  const i64vec2 p1 = front ? v1 : v2;
  const i64vec2 p2 = front ? v2 : v1;
  const uvec2 first = blockOf(epoch, x0, y0);
  const uvec2 last = blockOf(epoch, x1 - 1, y1 - 1);
  const uint columns = last.x - first.x + 1u;
  const uint blocks = columns * (last.y - first.y + 1u);
  // This invocation's chunk of the blocks, numbered row by row from `first`.
  const uint begin = min(chunk * frame.scatterBlocks, blocks);
  const uint end = min(begin + min(frame.scatterBlocks, blocks - begin), blocks);
  uint k = begin;
  for (; k < end; ++k) {
    const uvec2 b = first + uvec2(k % columns, k / columns);
    if (!blockMeetsTriangle(v0, p1, p2, epoch.gridOrigin + ivec2(b) * 8))
      continue;
    const uint job = epoch.firstJob + b.y * epoch.gridWidth + b.x;
    if (frame.binPass == 0u) {
      atomicAdd(binEntries[job], 1u);
    } else {
      const uint slot = atomicAdd(binCursors[job], 1u);
      if (slot < frame.entryCapacity)
        lists[slot] = t;
    }
  }
  if (k < end)
    atomicAdd(counters[kCounterScatterShort], 1u);
}
