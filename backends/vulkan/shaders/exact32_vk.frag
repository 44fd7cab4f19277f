#version 450
#extension GL_GOOGLE_include_directive : require
// The fragment stage of the Vulkan device without 64-bit shader arithmetic: exact_vk.frag's
// coverage and depth at this pixel's centre, in 32-bit words (exact_contract32.glsl). Row r of
// Vulkan's framebuffer is the contract's j = height - 1 - r, as in exact_vk.frag.

#include "exact_contract32.glsl"

layout(push_constant) uniform Frame {
  vec2 framebufferSize;
  float clearDepth;  // used by the clear pipeline only
} frame;

layout(location = 0) flat in ivec4 triV0V1;
layout(location = 1) flat in ivec2 triV2;
layout(location = 2) flat in int triFront;
layout(location = 3) flat in uvec2 planeZ0;
layout(location = 4) flat in uvec4 planeSlopes;

void main() {
  vec2 glWindow = vec2(gl_FragCoord.x, frame.framebufferSize.y - gl_FragCoord.y);
  ivec2 centre = pixelCentreFixed32(glWindow);
  ivec2 v0 = triV0V1.xy;
  if (!triangleCovers32(v0, triV0V1.zw, triV2, triFront != 0, centre))
    discard;
  uint q = quantizeDepth32(depthAt32(planeZ0, planeSlopes, v0, centre));
  gl_FragDepth = float(q) * (1.0 / 16777216.0);
}
