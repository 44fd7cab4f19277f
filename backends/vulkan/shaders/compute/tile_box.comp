#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's box stage: posed blocks' world boxes (raster/posed_boxes.hpp), one workgroup a
// block (BoxJob): every vertex to
// world by the pose as the vertex stage does (docs/rasterization.md section 2.1: each operation
// `precise`, in the contract's order), then per axis the smallest and largest coordinate, a
// stride of the vertices an invocation and a tree over the workgroup. A minimum or maximum of
// doubles that are neither NaN nor zero is the same bits in any order; a box whose extreme is a
// zero, or that met a NaN, is flagged for the host to make again in its own order.

layout(local_size_x = 64) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 14) readonly buffer BoxJobs { BoxJob boxJobs[]; };
// Twelve doubles a block: its pose's linear part row by row, then its translation.
layout(std430, set = 0, binding = 21) readonly buffer Poses { double poses[]; };
layout(std430, set = 0, binding = 15) writeonly buffer Boxes { double boxes[]; };

shared double lows[3][64];
shared double highs[3][64];
shared uint sawNaN[64];

void main() {
  const uint block = linearWorkgroup();
  if (block >= frame.boxJobs)
    return;  // uniform over the workgroup: no barrier is skipped by some invocations only
  const BoxJob job = boxJobs[block];
  DoubleWords localData = DoubleWords(job.local);
  const uint vertices = job.vertexCount;
  const uint lane = gl_LocalInvocationID.x;
  const uint p = 12u * job.pose;
  const double infinity = int64BitsToDouble(0x7FF0000000000000l);
  dvec3 low = dvec3(infinity);
  dvec3 high = dvec3(-infinity);
  bool nan = false;
  for (uint v = lane; v < vertices; v += 64u) {
    const double p0 = localData.values[3u * v];
    const double p1 = localData.values[3u * v + 1u];
    const double p2 = localData.values[3u * v + 2u];
    precise double wx = ((poses[p] * p0 + poses[p + 1u] * p1) + poses[p + 2u] * p2) + poses[p + 9u];
    precise double wy =
        ((poses[p + 3u] * p0 + poses[p + 4u] * p1) + poses[p + 5u] * p2) + poses[p + 10u];
    precise double wz =
        (poses[p + 6u] * p0 + (poses[p + 7u] * p1 + poses[p + 8u] * p2)) + poses[p + 11u];
    const dvec3 w = dvec3(wx, wy, wz);
    for (int k = 0; k < 3; ++k) {
      if (isnan(w[k])) {
        nan = true;
      } else {
        low[k] = w[k] < low[k] ? w[k] : low[k];
        high[k] = w[k] > high[k] ? w[k] : high[k];
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    lows[k][lane] = low[k];
    highs[k][lane] = high[k];
  }
  sawNaN[lane] = nan ? 1u : 0u;
  barrier();
  for (uint stride = 32u; stride > 0u; stride >>= 1) {
    if (lane < stride) {
      for (int k = 0; k < 3; ++k) {
        const double a = lows[k][lane + stride];
        lows[k][lane] = a < lows[k][lane] ? a : lows[k][lane];
        const double b = highs[k][lane + stride];
        highs[k][lane] = b > highs[k][lane] ? b : highs[k][lane];
      }
      sawNaN[lane] |= sawNaN[lane + stride];
    }
    barrier();
  }
  if (lane == 0u) {
    bool orderMatters = sawNaN[0] != 0u;
    for (int k = 0; k < 3; ++k) {
      boxes[8u * block + uint(k)] = lows[k][0];
      boxes[8u * block + 3u + uint(k)] = highs[k][0];
      orderMatters = orderMatters || lows[k][0] == 0.0 || highs[k][0] == 0.0;
    }
    boxes[8u * block + 6u] = orderMatters ? 1.0 : 0.0;
    boxes[8u * block + 7u] = 0.0;
  }
}
