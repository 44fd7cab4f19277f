// The exact GL device's fragment stage: the contract's coverage test (64-bit edge functions,
// bottom-left fill rule) and depth (plane in double, quantised to 24 bits) at this pixel's
// centre. The quantised q is written as q 2^-24 into a 32-bit float depth buffer, where it is
// exact, so the fixed-function depth compare is the contract's integer compare. The stencil
// test and update stay fixed-function.

flat in ivec4 triV0V1;
flat in ivec2 triV2;
flat in int triFront;
flat in double planeZ0;
flat in dvec2 planeSlopes;

void main() {
  i64vec2 centre = pixelCentreFixed(gl_FragCoord.xy);
  i64vec2 v0 = i64vec2(triV0V1.xy);
  i64vec2 v1 = i64vec2(triV0V1.zw);
  i64vec2 v2 = i64vec2(triV2);
  if (!triangleCovers(v0, v1, v2, triFront != 0, centre))
    discard;
  uint q = quantizeDepth(depthAt(planeZ0, planeSlopes, v0, centre));
  gl_FragDepth = float(q) * (1.0 / 16777216.0);
}
