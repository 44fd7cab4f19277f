#version 450
// The pixel summary (raster/include/recode/raster/pixel_summary.hpp, summarizePixels) of one
// rectangle, worked out by one workgroup (a dispatch summarises many rectangles): the stencil's pixels counted by class, the marked
// pixels' bounding rectangle and, with a near end, their depth intervals. Every reduction is an
// integer count, minimum or maximum, so the order the invocations meet in does not matter and
// the words equal the host's. Integer arithmetic only: the same SPIR-V serves the devices with
// and without 64-bit shader arithmetic.

layout(local_size_x = 256) in;

// Copies of the rectangle as vkCmdCopyImageToBuffer packs them: rows from the top of the image
// (GL's y1 - 1) down, one byte per stencil value, one 32-bit float per depth value.
layout(std430, set = 0, binding = 0) readonly buffer NearScratch { uint nearWords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Scratch { uint words[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Results { uint results[]; };

// Each summary's parameters, eleven words in the order of `Summary` below: workgroup k of a
// dispatch summarises the k-th from `firstWord` on. The summaries recorded since the last
// submission are summarised by one dispatch (one per set of buffers), recorded just before the
// submission.
layout(std430, set = 0, binding = 3) readonly buffer Summaries { uint parameters[]; };

layout(push_constant) uniform Dispatch { uint firstWord; } dispatch;

struct Summary {
  uint stencilByte;  // in Scratch: the stencil copy
  uint farWord;      // in Scratch: the depth now (the far ends)
  uint tableWord;    // in Scratch: 64 words, four stencil values' classes a word
  uint nearWord;     // in NearScratch: the kept depth (the near ends)
  uint resultWord;   // in Results: the 16 words
  uint x0;           // the rectangle: left column, top row + 1 (GL), size
  uint y1;
  uint width;
  uint height;
  uint marked;     // bit c: class c is marked
  uint withDepth;  // 1: summarise the depth intervals too
};

const uint kClasses = 10u;  // kMaxStencilClasses
const uint kNone = 0xFFFFFFFFu;

shared uint sharedCounts[kClasses];
shared uint sharedX0, sharedY0, sharedX1, sharedY1;
shared uint sharedNearest, sharedFarthest, sharedLongest, sharedInverted, sharedBad;

// A stored depth as the 24-bit integer q with value q 2^-24 (what depthFromStoredFloats
// makes on the host), by the float's bits rather than float arithmetic, so that a device that
// flushes subnormals cannot make one valid. Returns kNone when the value is no such multiple.
uint storedDepth(uint bits) {
  if ((bits & 0x7FFFFFFFu) == 0u)
    return 0u;  // +0 and -0
  if ((bits & 0x80000000u) != 0u)
    return kNone;
  const uint exponent = bits >> 23;  // biased; below 126 the value is below 1/2
  if (exponent == 0u || exponent > 126u)
    return kNone;  // subnormal, or 1 and beyond
  const uint significand = (bits & 0x7FFFFFu) | 0x800000u;
  const uint shift = 126u - exponent;  // value 2^24 = significand 2^-shift
  if (shift >= 24u || (significand & ((1u << shift) - 1u)) != 0u)
    return kNone;
  return significand >> shift;
}

Summary pc;

uint stencilAt(uint i) {
  const uint byteIndex = pc.stencilByte + i;
  return (words[byteIndex >> 2] >> ((byteIndex & 3u) * 8u)) & 0xFFu;
}

uint classOf(uint stencil) {
  return (words[pc.tableWord + (stencil >> 2)] >> ((stencil & 3u) * 8u)) & 0xFFu;
}

void main() {
  const uint base = dispatch.firstWord + 11u * gl_WorkGroupID.x;
  pc = Summary(parameters[base], parameters[base + 1u], parameters[base + 2u],
               parameters[base + 3u], parameters[base + 4u], parameters[base + 5u],
               parameters[base + 6u], parameters[base + 7u], parameters[base + 8u],
               parameters[base + 9u], parameters[base + 10u]);
  const uint lane = gl_LocalInvocationID.x;
  if (lane < kClasses)
    sharedCounts[lane] = 0u;
  if (lane == 0u) {
    sharedX0 = kNone;
    sharedY0 = kNone;
    sharedX1 = 0u;
    sharedY1 = 0u;
    sharedNearest = kNone;
    sharedFarthest = 0u;
    sharedLongest = 0u;
    sharedInverted = 0u;
    sharedBad = 0u;
  }
  barrier();

  uint counts[kClasses];
  for (uint c = 0u; c < kClasses; ++c)
    counts[c] = 0u;
  uint x0 = kNone, y0 = kNone, x1 = 0u, y1 = 0u;
  uint nearest = kNone, farthest = 0u, longest = 0u, inverted = 0u, bad = 0u;
  const uint pixels = pc.width * pc.height;
  for (uint i = lane; i < pixels; i += 256u) {
    const uint c = classOf(stencilAt(i));
    counts[c] += 1u;
    if (((pc.marked >> c) & 1u) == 0u)
      continue;
    const uint x = pc.x0 + i % pc.width;
    const uint y = pc.y1 - 1u - i / pc.width;
    x0 = min(x0, x);
    y0 = min(y0, y);
    x1 = max(x1, x + 1u);
    y1 = max(y1, y + 1u);
    if (pc.withDepth == 0u)
      continue;
    uint lo = storedDepth(nearWords[pc.nearWord + i]);
    uint hi = storedDepth(words[pc.farWord + i]);
    if (lo == kNone || hi == kNone) {
      bad = 1u;
      continue;
    }
    if (lo > hi) {
      inverted += 1u;
      lo = lo / 2u + hi / 2u + (lo & hi & 1u);  // intervalMidpoint
      hi = lo;
    }
    nearest = min(nearest, lo);
    farthest = max(farthest, hi);
    longest = max(longest, hi - lo);
  }

  for (uint c = 0u; c < kClasses; ++c)
    if (counts[c] != 0u)
      atomicAdd(sharedCounts[c], counts[c]);
  if (x1 != 0u) {
    atomicMin(sharedX0, x0);
    atomicMin(sharedY0, y0);
    atomicMax(sharedX1, x1);
    atomicMax(sharedY1, y1);
    atomicMin(sharedNearest, nearest);
    atomicMax(sharedFarthest, farthest);
    atomicMax(sharedLongest, longest);
    atomicAdd(sharedInverted, inverted);
    atomicMax(sharedBad, bad);
  }
  barrier();

  if (lane != 0u)
    return;
  const uint at = pc.resultWord;
  for (uint c = 0u; c < kClasses; ++c)
    results[at + c] = sharedCounts[c];
  const bool anyMarked = sharedX1 != 0u;
  results[at + 10u] = anyMarked ? (sharedX0 | (sharedX1 << 16)) : 0u;
  results[at + 11u] = anyMarked ? (sharedY0 | (sharedY1 << 16)) : 0u;
  const bool depth = anyMarked && pc.withDepth != 0u;
  results[at + 12u] = depth ? (sharedBad != 0u ? kNone : sharedNearest) : 0u;
  results[at + 13u] = depth ? sharedFarthest : 0u;
  results[at + 14u] = depth ? sharedLongest : 0u;
  results[at + 15u] = depth ? sharedInverted : 0u;
}
