#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
// The exact Vulkan device's vertex stage (docs/backends.md): one instance per triangle, drawn as
// a proxy rectangle of four vertices over the pixels whose centres the triangle can cover, as on
// GL. Positions are computed in GL window coordinates (y up); the device's negative-height
// viewport maps them onto Vulkan's framebuffer (y down), which also keeps GL's winding, so a
// counter-clockwise proxy is front-facing with VK_FRONT_FACE_COUNTER_CLOCKWISE.

#include "exact_contract.glsl"

layout(location = 0) in ivec4 pixelRect;  // proxy [x0, x1) x [y0, y1) in pixels
layout(location = 1) in ivec4 fixedV0V1;  // snapped (X0, Y0, X1, Y1), 24.8 fixed point
layout(location = 2) in ivec2 fixedV2;    // snapped (X2, Y2)
layout(location = 3) in vec3 vertexZ;     // z0, z1, z2 as submitted
layout(location = 4) in int frontFacing;  // sign of the snapped area: 1 front, 0 back
layout(location = 5) in uvec4 slopeBits;  // dzdx, dzdy as set up on the CPU, low words first

layout(push_constant) uniform Frame {
  vec2 framebufferSize;
  float clearDepth;  // used by the clear pipeline only
} frame;

layout(location = 0) flat out ivec4 triV0V1;
layout(location = 1) flat out ivec2 triV2;
layout(location = 2) flat out int triFront;
layout(location = 3) flat out double planeZ0;
layout(location = 4) flat out dvec2 planeSlopes;

void main() {
  // Strip order (x0,y0) (x1,y0) (x0,y1) (x1,y1) winds counter-clockwise in GL window
  // coordinates; mirrored in x it winds clockwise, so the proxy's facing selects the
  // triangle's front or back stencil ops.
  bool right = (gl_VertexIndex & 1) != 0;
  bool top = (gl_VertexIndex & 2) != 0;
  if (frontFacing == 0)
    right = !right;
  vec2 corner = vec2(right ? pixelRect.z : pixelRect.x, top ? pixelRect.w : pixelRect.y);
  gl_Position = vec4(corner / frame.framebufferSize * 2.0 - 1.0, 0.0, 1.0);

  triV0V1 = fixedV0V1;
  triV2 = fixedV2;
  triFront = frontFacing;
  planeZ0 = double(vertexZ.x);
  // The slopes come set up (backends::buildProxyTriangles, the contract's operation order and
  // correctly rounded division): passed on bit for bit.
  planeSlopes = dvec2(packDouble2x32(slopeBits.xy), packDouble2x32(slopeBits.zw));
}
