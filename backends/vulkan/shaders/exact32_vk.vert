#version 450
#extension GL_GOOGLE_include_directive : require
// The vertex stage of the Vulkan device without 64-bit shader arithmetic (VulkanDevice with
// ShaderArithmetic::Emulated32): exact_vk.vert's proxy rectangle, with the plane's z0 and slopes
// passed on as doubles' bit patterns in 32-bit words (exact_contract32.glsl) instead of doubles.
// z arrives as the floats' bits (a UINT attribute format), so no float operation, which a GPU
// may let flush a subnormal float to zero, touches it.

#include "exact_contract32.glsl"

layout(location = 0) in ivec4 pixelRect;  // proxy [x0, x1) x [y0, y1) in pixels
layout(location = 1) in ivec4 fixedV0V1;  // snapped (X0, Y0, X1, Y1), 24.8 fixed point
layout(location = 2) in ivec2 fixedV2;    // snapped (X2, Y2)
layout(location = 3) in uvec3 vertexZ;    // the bits of z0, z1, z2 as submitted
layout(location = 4) in int frontFacing;  // sign of the snapped area: 1 front, 0 back
layout(location = 5) in uvec4 slopeBits;  // dzdx, dzdy as set up on the CPU, low words first

layout(push_constant) uniform Frame {
  vec2 framebufferSize;
  float clearDepth;  // used by the clear pipeline only
} frame;

layout(location = 0) flat out ivec4 triV0V1;
layout(location = 1) flat out ivec2 triV2;
layout(location = 2) flat out int triFront;
layout(location = 3) flat out uvec2 planeZ0;      // (double) z0's bits
layout(location = 4) flat out uvec4 planeSlopes;  // dzdx, dzdy's bits

void main() {
  // As exact_vk.vert: the strip winds counter-clockwise in GL window coordinates, mirrored in x
  // for a back-facing triangle so that the proxy takes its back stencil ops.
  bool right = (gl_VertexIndex & 1) != 0;
  bool top = (gl_VertexIndex & 2) != 0;
  if (frontFacing == 0)
    right = !right;
  vec2 corner = vec2(right ? pixelRect.z : pixelRect.x, top ? pixelRect.w : pixelRect.y);
  gl_Position = vec4(corner / frame.framebufferSize * 2.0 - 1.0, 0.0, 1.0);

  triV0V1 = fixedV0V1;
  triV2 = fixedV2;
  triFront = frontFacing;
  planeZ0 = doubleFromFloatBits(vertexZ.x);
  planeSlopes = slopeBits;
}
