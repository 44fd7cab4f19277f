// The exact GL device's vertex stage (docs/backends.md): one instance per triangle, drawn as a
// proxy rectangle of four vertices over the pixels whose centres the triangle can cover. The
// triangle's snapped vertices, first depth and depth-plane slopes (set up on the CPU) ride along
// as flat values, and the fragment stage applies the contract's coverage and depth.

layout(location = 0) in ivec4 pixelRect;  // proxy [x0, x1) x [y0, y1) in pixels
layout(location = 1) in ivec4 fixedV0V1;  // snapped (X0, Y0, X1, Y1), 24.8 fixed point
layout(location = 2) in ivec2 fixedV2;    // snapped (X2, Y2)
layout(location = 3) in vec3 vertexZ;     // z0, z1, z2 as submitted
layout(location = 4) in int frontFacing;  // sign of the snapped area: 1 front, 0 back
layout(location = 5) in uvec4 slopeBits;  // dzdx, dzdy as set up on the CPU, low words first

uniform vec2 framebufferSize;

flat out ivec4 triV0V1;
flat out ivec2 triV2;
flat out int triFront;
flat out double planeZ0;
flat out dvec2 planeSlopes;

void main() {
  // Strip order (x0,y0) (x1,y0) (x0,y1) (x1,y1) winds counter-clockwise; mirrored in x it winds
  // clockwise, so GL's own facing of the proxy selects the triangle's front or back stencil ops.
  bool right = (gl_VertexID & 1) != 0;
  bool top = (gl_VertexID & 2) != 0;
  if (frontFacing == 0)
    right = !right;
  vec2 corner = vec2(right ? pixelRect.z : pixelRect.x, top ? pixelRect.w : pixelRect.y);
  gl_Position = vec4(corner / framebufferSize * 2.0 - 1.0, 0.0, 1.0);

  triV0V1 = fixedV0V1;
  triV2 = fixedV2;
  triFront = frontFacing;
  planeZ0 = double(vertexZ.x);
  // The slopes come set up (backends::buildProxyTriangles, the contract's operation order and
  // correctly rounded division): passed on bit for bit.
  planeSlopes = dvec2(packDouble2x32(slopeBits.xy), packDouble2x32(slopeBits.zw));
}
