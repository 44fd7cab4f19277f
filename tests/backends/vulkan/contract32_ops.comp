#version 450
#extension GL_GOOGLE_include_directive : require
// Runs one function of exact_contract32.glsl over a buffer of operands, for the arithmetic test
// (contract32_arithmetic_test.cpp), which compares every result with the CPU's int64_t and
// double arithmetic bit for bit.

#include "exact_contract32.glsl"

layout(local_size_x = 64) in;

struct Operands {
  uvec4 a;
  uvec4 b;
  uvec4 c;
};

layout(std430, binding = 0) readonly buffer Inputs {
  Operands operands[];
};
layout(std430, binding = 1) writeonly buffer Outputs {
  uvec4 results[];
};
layout(push_constant) uniform Job {
  uint op;  // Contract32Op in contract32_arithmetic_test.cpp
  uint count;
} job;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= job.count)
    return;
  Operands o = operands[i];
  uvec4 r = uvec4(0u);
  if (job.op == 0u) {
    r.xy = multiplyByInteger(o.a.xy, int(o.b.x));
  } else if (job.op == 1u) {
    r.xy = addDoubles(o.a.xy, o.b.xy);
  } else if (job.op == 2u) {
    r.x = quantizeDepth32(o.a.xy);
  } else if (job.op == 3u) {
    r.xy = doubleFromFloatBits(o.a.x);
  } else if (job.op == 4u) {
    // a: z0's float bits, X0, Y0; b: the slopes' bits; c: the centre
    uvec2 z = depthAt32(doubleFromFloatBits(o.a.x), o.b, ivec2(o.a.yz), ivec2(o.c.xy));
    r.xy = z;
    r.z = quantizeDepth32(z);
  } else if (job.op == 5u) {
    // a: v0, v1; b: v2, front; c: the centre
    r.x = triangleCovers32(ivec2(o.a.xy), ivec2(o.a.zw), ivec2(o.b.xy), o.b.z != 0u,
                           ivec2(o.c.xy)) ? 1u : 0u;
    // The edge function of a -> b alone, as words, and its fill-rule verdict.
    int dx = int(o.a.z) - int(o.a.x);
    int dy = int(o.a.w) - int(o.a.y);
    r.yz = sub64(signedWideProduct(dx, int(o.c.y) - int(o.a.y)),
                 signedWideProduct(dy, int(o.c.x) - int(o.a.x)));
    r.w = edgeCovers32(ivec2(o.a.xy), ivec2(o.a.zw), ivec2(o.c.xy)) ? 1u : 0u;
  }
  results[i] = r;
}
