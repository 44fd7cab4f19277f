#version 450
#extension GL_GOOGLE_include_directive : require
// Stage 2 of the compute device's tile rasterizer: the exclusive prefix sum of the blocks'
// counts, in one workgroup: each block's list starts where the lists of the blocks before it
// end, so the bins' list is the blocks' lists one after the other. The scatter's cursors start
// at the same offsets.

layout(local_size_x = 256) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 3) readonly buffer BlockCounts { uint blockCounts[]; };
layout(std430, set = 0, binding = 4) writeonly buffer BlockOffsets { uint blockOffsets[]; };
layout(std430, set = 0, binding = 5) writeonly buffer BlockCursors { uint blockCursors[]; };

shared uint partial[256];

void main() {
  const uint blocks = draw.gridWidth * draw.gridHeight;
  const uint lane = gl_LocalInvocationID.x;
  const uint span = (blocks + 255u) / 256u;  // consecutive blocks per invocation
  const uint first = min(lane * span, blocks);
  const uint last = min(first + span, blocks);
  uint sum = 0u;
  for (uint b = first; b < last; ++b)
    sum += blockCounts[b];
  partial[lane] = sum;
  barrier();
  // Hillis-Steele inclusive scan of the 256 partial sums.
  for (uint step = 1u; step < 256u; step <<= 1u) {
    const uint add = lane >= step ? partial[lane - step] : 0u;
    barrier();
    partial[lane] += add;
    barrier();
  }
  uint offset = partial[lane] - sum;
  for (uint b = first; b < last; ++b) {
    blockOffsets[b] = offset;
    blockCursors[b] = offset;
    offset += blockCounts[b];
  }
}
