#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's vertex stage (docs/rasterization.md section 2.1, raster/vertex_stage.hpp), one
// invocation a vertex of every posed mesh the frame draws (VertexJob): the block's object-space
// vertex to world by the pose (tile_common.glsl's poseVertex), to window by the view's mapping,
// x and y snapped to the 1/256-pixel grid and z rounded to float. Every double operation is
// `precise` and in the contract's order; the divisions are correctly rounded
// (exact_contract.glsl) and the rounding to float is done on the bits, so no driver's accuracy
// or denormal handling enters. The source promised that every vertex maps inside the window's
// range (TriangleSource::posedMesh), so nothing here checks.

layout(local_size_x = 64) in;

#include "exact_contract.glsl"
#include "tile_common.glsl"
#include "tile_frame_inputs.glsl"

layout(std430, set = 0, binding = 4) readonly buffer VertexJobs { VertexJob vertexJobs[]; };
// Each VertexJob's transform, 23 doubles: the linear part row by row (0-8), the translation
// (9-11), umin, urange, width (12-14), vmin, vrange, height (15-17), depthMax, depthRange (18,
// 19), and the world coordinates of u, v and d as small whole numbers (20-22).
layout(std430, set = 0, binding = 5) readonly buffer Transforms { double transforms[]; };

uint transformAt;  // this invocation's transform's first double

// Word k of this invocation's transform.
double T(int k) {
  return transforms[transformAt + uint(k)];
}

// The job that holds frame vertex i: the last whose firstVertex <= i.
uint jobOfVertex(uint i) {
  uint found;
  LAST_AT_OR_BELOW(found, vertexJobs, firstVertex, frame.vertexJobs, i);
  return found;
}

// a / b rounded to nearest even, the sign of a zero quotient kept (a zero numerator's sign
// decides it, as in IEEE division).
double quotient(double a, double b) {
  if (a == 0.0) {
    precise double zero = a / b;
    return zero;
  }
  return divideRoundedToNearest(a, b);
}

// snapToSubpixel: nearbyint(x 256) / 256 as a float. |x 256| <= 2^23 (the source's promise), so
// the result is exact in float; a zero keeps the sign nearbyint gives it (that of x).
float snapToGrid(double x) {
  precise double scaled = x * 256.0;
  const int64_t steps = roundToNearestEven(scaled);
  if (steps == 0l)
    return doubleBitsToInt64(x) < 0l ? uintBitsToFloat(0x80000000u) : 0.0;
  precise double snapped = double(steps) * 0.00390625;
  return float(snapped);
}

// The float nearest to v, ties to even, from v's bits (0 <= |v| <= 1 here: no overflow).
float nearestFloat(double v) {
  const uint64_t bits = uint64_t(doubleBitsToInt64(v));
  const uint sign = uint(bits >> 63) << 31;
  const int exponent = int((bits >> 52) & 0x7FFul);
  if (exponent == 0)  // zero, or a double denormal: far below the smallest float
    return uintBitsToFloat(sign);
  const uint64_t significand = (bits & 0xFFFFFFFFFFFFFul) | (1ul << 52);
  // A float keeps 24 significant bits when normal; below 2^-126 fewer, down to none.
  const int floatExponent = exponent - 1023 + 127;
  const int shift = floatExponent >= 1 ? 29 : 29 + (1 - floatExponent);
  if (shift > 54)
    return uintBitsToFloat(sign);
  const uint64_t kept = significand >> uint(shift);
  const uint64_t rest = significand & ((1ul << uint(shift)) - 1ul);
  const uint64_t halfway = 1ul << uint(shift - 1);
  const bool up = rest > halfway || (rest == halfway && (kept & 1ul) != 0ul);
  uint64_t rounded = kept + (up ? 1ul : 0ul);
  // Normal: the exponent above the 23 stored bits (a carry out of them raises it by one).
  // Denormal: the kept bits are the whole encoding (a carry makes the smallest normal).
  if (floatExponent >= 1)
    rounded += uint64_t(floatExponent - 1) << 23;
  return uintBitsToFloat(sign | uint(rounded));
}

void main() {
  const uint frameVertex = linearInvocation();
  if (frameVertex >= frame.vertexCount)
    return;
  const VertexJob job = vertexJobs[jobOfVertex(frameVertex)];
  const uint i = frameVertex - job.firstVertex;
  transformAt = 23u * job.transform;
  DoubleWords localData = DoubleWords(job.local);
  FloatWords vertexData = FloatWords(job.windows);
  const dvec3 local = dvec3(localData.values[3u * i], localData.values[3u * i + 1u],
                            localData.values[3u * i + 2u]);
  const dvec3 world = poseVertex(dvec3(T(0), T(1), T(2)), dvec3(T(3), T(4), T(5)),
                                 dvec3(T(6), T(7), T(8)), dvec3(T(9), T(10), T(11)), local);
  const double u = world[int(T(20))];
  const double v = world[int(T(21))];
  const double d = world[int(T(22))];
  // mapToWindow: x = (u - umin) / urange width, y likewise, z = (depthMax - d) / depthRange.
  precise double du = u - T(12);
  precise double x = quotient(du, T(13)) * T(14);
  precise double dv = v - T(15);
  precise double y = quotient(dv, T(16)) * T(17);
  precise double dd = T(18) - d;
  const double z = quotient(dd, T(19));
  vertexData.values[3u * i] = snapToGrid(x);
  vertexData.values[3u * i + 1u] = snapToGrid(y);
  vertexData.values[3u * i + 2u] = nearestFloat(z);
}
