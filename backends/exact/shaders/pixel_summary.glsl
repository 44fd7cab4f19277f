// The pixel summary (raster/include/recode/raster/pixel_summary.hpp, summarizePixels) of one
// rectangle, worked out by one workgroup of 256 invocations: the stencil's pixels counted by
// class, the marked pixels' bounding rectangle and, with a near end, their depth intervals.
// Every reduction is an integer count, minimum or maximum, so the order the invocations meet in
// does not matter and the words equal the host's. Integer arithmetic only, so it serves devices
// with and without 64-bit shader arithmetic.
//
// Included by each API's compute stage (backends/vulkan/shaders/summary_vk.comp,
// backends/gl/shaders/summary_gl.comp), which declares local_size_x = 256 and the buffers:
//   nearWords[]   the kept depth (the near ends), 32-bit floats
//   words[]       the stencil copy (a byte a pixel), the depth now (the far ends), the class
//                 table (64 words, four stencil values' classes a word)
//   results[]     16 words a summary
//   parameters[]  each summary's Summary, thirteen words in the order below
// and calls summarize(base) with the index of the summary's first parameter word.

// Where a summary's inputs are, in words or bytes of the buffers above, and its rectangle.
struct Summary {
  uint stencilByte;     // in words: the stencil copy, a byte a pixel
  uint farWord;         // in words: the depth now (the far ends)
  uint tableWord;       // in words: the class table
  uint nearWord;        // in nearWords: the kept depth (the near ends)
  uint resultWord;      // in results: the 16 words
  uint x0;              // the rectangle: left column, first row, last row + 1 (GL), width,
  uint y0;              // height
  uint y1;
  uint width;
  uint height;
  uint marked;          // bit c: class c is marked
  uint withDepth;       // 1: summarise the depth intervals too
  uint rowsFromBottom;  // 1: the copies' rows run from y0 up (GL), 0: from y1 - 1 down (Vulkan)
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

Summary pc;  // the summary this workgroup makes

uint stencilAt(uint i) {
  const uint byteIndex = pc.stencilByte + i;
  return (words[byteIndex >> 2] >> ((byteIndex & 3u) * 8u)) & 0xFFu;
}

uint classOf(uint stencil) {
  return (words[pc.tableWord + (stencil >> 2)] >> ((stencil & 3u) * 8u)) & 0xFFu;
}

// Makes the summary whose parameters start at parameters[base].
void summarize(uint base) {
  pc = Summary(parameters[base], parameters[base + 1u], parameters[base + 2u],
               parameters[base + 3u], parameters[base + 4u], parameters[base + 5u],
               parameters[base + 6u], parameters[base + 7u], parameters[base + 8u],
               parameters[base + 9u], parameters[base + 10u], parameters[base + 11u],
               parameters[base + 12u]);
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
    const uint row = i / pc.width;
    const uint y = pc.rowsFromBottom != 0u ? pc.y0 + row : pc.y1 - 1u - row;
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
