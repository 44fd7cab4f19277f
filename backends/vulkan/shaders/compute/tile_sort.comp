#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's binning, last: each job's list in index order (command order), one
// invocation a job. The scatter filled the lists through atomic cursors, in no particular
// order; a heapsort in place puts each back into the order the contract draws in, with no shared
// memory and no barrier (which cost a CPU driver such as lavapipe more than the sort itself). A
// job whose list did not fit is left alone: the raster stage draws it from every triangle.

layout(local_size_x = 64) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) readonly buffer BinCounts { uint blockCounts[]; };
layout(std430, set = 0, binding = 8) readonly buffer BinOffsets { uint blockOffsets[]; };
layout(std430, set = 0, binding = 10) buffer Pairs { uint pairs[]; };

// Moves the entry at `root` down the max-heap pairs[offset, offset + n) until it is in place.
void siftDown(uint offset, uint root, uint n) {
  const uint value = pairs[offset + root];
  uint at = root;
  for (;;) {
    uint child = 2u * at + 1u;
    if (child >= n)
      break;
    if (child + 1u < n && pairs[offset + child + 1u] > pairs[offset + child])
      child += 1u;
    if (pairs[offset + child] <= value)
      break;
    pairs[offset + at] = pairs[offset + child];
    at = child;
  }
  pairs[offset + at] = value;
}

void main() {
  const uint block = linearInvocation();
  if (block >= frame.jobCount)
    return;
  const uint n = blockCounts[block];
  const uint offset = blockOffsets[block];
  if (n < 2u || offset + n > frame.pairCapacity)
    return;
  for (uint root = n / 2u; root > 0u; --root)
    siftDown(offset, root - 1u, n);
  for (uint end = n - 1u; end > 0u; --end) {
    const uint largest = pairs[offset];
    pairs[offset] = pairs[offset + end];
    pairs[offset + end] = largest;
    siftDown(offset, 0u, end);
  }
}
