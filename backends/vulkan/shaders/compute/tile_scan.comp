#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's binning, after the set-up: the exclusive prefix sum of the jobs'
// counts, in one workgroup: each job's list starts where the lists of the jobs before it
// end, so the bins' list is the jobs' lists one after the other. The scatter's cursors start
// at the same offsets.

layout(local_size_x = 256) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) readonly buffer BinCounts { uint blockCounts[]; };
layout(std430, set = 0, binding = 8) writeonly buffer BinOffsets { uint blockOffsets[]; };
layout(std430, set = 0, binding = 9) writeonly buffer BinCursors { uint blockCursors[]; };

shared uint partial[256];

void main() {
  const uint blocks = frame.jobCount;
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
