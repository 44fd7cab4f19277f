#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's binning, between the scatter's two passes: the exclusive prefix sum of the jobs'
// entries (BinEntries), in one workgroup: each job's list starts where the lists of the jobs
// before it end, so Lists holds the jobs' lists one after the other. The scatter's cursors start
// at the same offsets.

layout(local_size_x = 256) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) readonly buffer BinEntries { uint binEntries[]; };
layout(std430, set = 0, binding = 8) writeonly buffer BinOffsets { uint binOffsets[]; };
layout(std430, set = 0, binding = 9) writeonly buffer BinCursors { uint binCursors[]; };

shared uint partial[256];

void main() {
  const uint jobs = frame.jobCount;
  const uint lane = gl_LocalInvocationID.x;
  const uint span = (jobs + 255u) / 256u;  // consecutive jobs per invocation
  const uint first = min(lane * span, jobs);
  const uint last = min(first + span, jobs);
  uint sum = 0u;
  for (uint j = first; j < last; ++j)
    sum += binEntries[j];
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
  for (uint j = first; j < last; ++j) {
    binOffsets[j] = offset;
    binCursors[j] = offset;
    offset += binEntries[j];
  }
}
