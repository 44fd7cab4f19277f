#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's binning, last: each job's list in index order (command order). The scatter filled
// the lists through atomic cursors, in no particular order; a heapsort in place puts each back
// into the order the contract draws in, with no shared memory and no barrier (which cost a CPU
// driver such as lavapipe more than the sort itself). A job whose list did not fit is left
// alone: the raster stage draws it from every triangle.
//
// One invocation a job. A job is charged each sift's longest walk; one that would pass
// Frame.sortBudget (a CPU driver's loop limit shared by a SIMD bundle's lanes,
// tile_frame_budgets.hpp) stops between two sifts, keeps its next step in SortProgress and asks
// for the next round (tile_rounds.glsl), which goes on from there. A job whose list is in order
// counts itself in Counters, which the host checks.

layout(local_size_x = 64) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) readonly buffer BinCounts { uint blockCounts[]; };
layout(std430, set = 0, binding = 8) readonly buffer BinOffsets { uint blockOffsets[]; };
layout(std430, set = 0, binding = 10) buffer Pairs { uint pairs[]; };
// A suspended job's round to go on in and its next step (written and read by its one lane).
layout(std430, set = 0, binding = 22) buffer SortProgress { uvec2 sortProgress[]; };
layout(std430, set = 0, binding = 19) buffer Counters { uint counters[]; };
// The rounds' indirect dispatches, three words a round (tile_rounds.glsl).
layout(std430, set = 0, binding = 23) buffer SortRoundArgs { uint roundArgs[]; };

#include "tile_rounds.glsl"

// Whether a loop of this invocation ended other than at its own test (a driver's loop limit).
bool cut = false;

// Moves the entry at `root` down the max-heap pairs[offset, offset + n) until it is in place.
void siftDown(uint offset, uint root, uint n) {
  const uint value = pairs[offset + root];
  uint at = root;
  bool settled = false;
  for (;;) {
    uint child = 2u * at + 1u;
    if (child >= n) {
      settled = true;
      break;
    }
    if (child + 1u < n && pairs[offset + child + 1u] > pairs[offset + child])
      child += 1u;
    if (pairs[offset + child] <= value) {
      settled = true;
      break;
    }
    pairs[offset + at] = pairs[offset + child];
    at = child;
  }
  pairs[offset + at] = value;
  cut = cut || !settled;
}

// Step s of the heapsort of n entries: the first n / 2 build the heap (roots n/2 - 1 down to 0),
// the next n - 1 each move the largest entry left to the end of the unsorted part.
void sortStep(uint offset, uint n, uint s) {
  const uint builds = n / 2u;
  if (s < builds) {
    siftDown(offset, builds - 1u - s, n);
    return;
  }
  const uint end = n - 1u - (s - builds);
  const uint largest = pairs[offset];
  pairs[offset] = pairs[offset + end];
  pairs[offset + end] = largest;
  siftDown(offset, 0u, end);
}

void main() {
  const uint block = linearInvocation();
  if (block >= frame.jobCount)
    return;
  uint step = 0u;
  if (frame.round > 0u) {
    const uvec2 place = sortProgress[block];
    if (place.x != frame.round)
      return;  // sorted in an earlier round
    step = place.y;
  }
  const uint n = blockCounts[block];
  const uint offset = blockOffsets[block];
  if (n >= 2u && offset + n <= frame.pairCapacity) {
    const uint steps = n / 2u + n - 1u;
    // A sift walks at most findMSB(n) + 1 levels; the step's own loop test is one more.
    const uint stepCost = uint(findMSB(n)) + 2u;
    uint spent = 0u;
    for (; step < steps; ++step) {
      if (spent + stepCost > frame.sortBudget) {
        sortProgress[block] = uvec2(frame.round + 1u, step);
        askNextRound();
        return;
      }
      spent += stepCost;
      sortStep(offset, n, step);
    }
    cut = cut || step < steps;
  }
  if (!cut)
    atomicAdd(counters[kCounterSortedJobs], 1u);
}
