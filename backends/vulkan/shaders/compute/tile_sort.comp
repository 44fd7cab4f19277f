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

layout(std430, set = 0, binding = 7) readonly buffer BinEntries { uint binEntries[]; };
layout(std430, set = 0, binding = 8) readonly buffer BinOffsets { uint binOffsets[]; };
layout(std430, set = 0, binding = 10) buffer Lists { uint lists[]; };
// A suspended job's round to go on in and its next step (written and read by its one lane).
layout(std430, set = 0, binding = 22) buffer SortProgress { uvec2 sortProgress[]; };
layout(std430, set = 0, binding = 19) buffer Counters { uint counters[]; };
// The rounds' indirect dispatches, three words a round (tile_rounds.glsl).
layout(std430, set = 0, binding = 23) buffer SortRoundArgs { uint roundArgs[]; };

#include "tile_rounds.glsl"

// Whether a loop of this invocation ended other than at its own test (a driver's loop limit).
bool cut = false;

// Moves the entry at `root` down the max-heap lists[offset, offset + n) until it is in place.
void siftDown(uint offset, uint root, uint n) {
  const uint value = lists[offset + root];
  uint at = root;
  bool settled = false;
  for (;;) {
    uint child = 2u * at + 1u;
    if (child >= n) {
      settled = true;
      break;
    }
    if (child + 1u < n && lists[offset + child + 1u] > lists[offset + child])
      child += 1u;
    if (lists[offset + child] <= value) {
      settled = true;
      break;
    }
    lists[offset + at] = lists[offset + child];
    at = child;
  }
  lists[offset + at] = value;
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
  const uint largest = lists[offset];
  lists[offset] = lists[offset + end];
  lists[offset + end] = largest;
  siftDown(offset, 0u, end);
}

void main() {
  const uint job = linearInvocation();
  if (job >= frame.jobCount)
    return;
  uint step = 0u;
  if (frame.round > 0u) {
    const uvec2 place = sortProgress[job];
    if (place.x != frame.round)
      return;  // sorted in an earlier round
    step = place.y;
  }
  const uint n = binEntries[job];
  const uint offset = binOffsets[job];
  if (n >= 2u && offset + n <= frame.entryCapacity) {
    const uint steps = n / 2u + n - 1u;
    // A sift walks at most findMSB(n) + 1 levels; the step's own loop test is one more.
    const uint stepCost = uint(findMSB(n)) + 2u;
    uint spent = 0u;
    for (; step < steps; ++step) {
      if (spent + stepCost > frame.sortBudget) {
        sortProgress[job] = uvec2(frame.round + 1u, step);
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
