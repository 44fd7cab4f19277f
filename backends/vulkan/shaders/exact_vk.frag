#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// The exact Vulkan device's fragment stage: the contract's coverage and depth at this pixel's
// centre, as on GL. Vulkan's gl_FragCoord counts rows from the top of the framebuffer; the
// contract counts them from the bottom, so row r is the contract's j = height - 1 - r, whose
// centre is at height - gl_FragCoord.y (exact in float for every supported height).

#include "exact_contract.glsl"

layout(push_constant) uniform Frame {
  vec2 framebufferSize;
  float clearDepth;  // used by the clear pipeline only
} frame;

layout(location = 0) flat in ivec4 triV0V1;
layout(location = 1) flat in ivec2 triV2;
layout(location = 2) flat in int triFront;
layout(location = 3) flat in double planeZ0;
layout(location = 4) flat in dvec2 planeSlopes;

void main() {
  vec2 glWindow = vec2(gl_FragCoord.x, frame.framebufferSize.y - gl_FragCoord.y);
  i64vec2 centre = pixelCentreFixed(glWindow);
  i64vec2 v0 = i64vec2(triV0V1.xy);
  i64vec2 v1 = i64vec2(triV0V1.zw);
  i64vec2 v2 = i64vec2(triV2);
  if (!triangleCovers(v0, v1, v2, triFront != 0, centre))
    discard;
  uint q = quantizeDepth(depthAt(planeZ0, planeSlopes, v0, centre));
  gl_FragDepth = float(q) * (1.0 / 16777216.0);
}
