#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's box stage: posed blocks' world boxes (raster/posed_boxes.hpp), one workgroup a
// block (BoxJob): every vertex to world by the pose as the vertex stage does (tile_common.glsl's
// poseVertex), then per axis the smallest and largest coordinate, a stride of the vertices an
// invocation and a tree over the workgroup. A minimum or maximum of doubles that are neither NaN
// nor zero is the same bits in any order; a box whose extreme is a zero, or that met a NaN, is
// flagged for the host to make again in its own order.

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
  const dvec3 x = dvec3(poses[p], poses[p + 1u], poses[p + 2u]);
  const dvec3 y = dvec3(poses[p + 3u], poses[p + 4u], poses[p + 5u]);
  const dvec3 z = dvec3(poses[p + 6u], poses[p + 7u], poses[p + 8u]);
  const dvec3 t = dvec3(poses[p + 9u], poses[p + 10u], poses[p + 11u]);
  const double infinity = int64BitsToDouble(0x7FF0000000000000l);
  dvec3 low = dvec3(infinity);
  dvec3 high = dvec3(-infinity);
  bool nan = false;
  for (uint v = lane; v < vertices; v += 64u) {
    const dvec3 w = poseVertex(x, y, z, t,
                               dvec3(localData.values[3u * v], localData.values[3u * v + 1u],
                                     localData.values[3u * v + 2u]));
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
