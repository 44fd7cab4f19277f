// Whether a triangle can cover a pixel centre of an 8x8 block: the binning's test, shared by the
// set-up (which counts a triangle in the blocks that pass) and the scatter (which lists it in the
// same blocks). Each edge function is linear, so its largest value over the block's 64 centres is
// at one of the four corner centres; a block where some edge is below its fill-rule bias at all
// four (E' < 0, docs/rasterization.md section 4) holds no covered centre and is left out, which
// drops most of the blocks of a long sliver's bounding box. Needs GL_ARB_gpu_shader_int64.

// The fill rule's bias of an edge of a counter-clockwise triangle going (dx, dy): 0 on an
// inclusive (top or left) edge, 1 on another (docs/rasterization.md section 4).
int64_t fillRuleBias(int64_t dx, int64_t dy) {
  return (dy < 0l || (dy == 0l && dx > 0l)) ? 0l : 1l;
}

// The largest of E' = dx (Y - Ya) - dy (X - Xa) - bias over the corner centres of the block whose
// lower-left pixel is `corner`, for the directed edge a -> b of a counter-clockwise triangle.
int64_t largestEdgeValue(i64vec2 a, i64vec2 b, ivec2 corner) {
  const int64_t dx = b.x - a.x;
  const int64_t dy = b.y - a.y;
  const int64_t bias = fillRuleBias(dx, dy);
  // E grows with Y when dx > 0 and with X when dy < 0: take the corner that maximises each term.
  const int64_t x = int64_t(corner.x) * 256l + 128l + (dy < 0l ? 7l * 256l : 0l);
  const int64_t y = int64_t(corner.y) * 256l + 128l + (dx > 0l ? 7l * 256l : 0l);
  return dx * (y - a.y) - dy * (x - a.x) - bias;
}

// Whether the counter-clockwise triangle (v0, p1, p2) may cover a centre of the 8x8 block whose
// lower-left pixel is `corner`.
bool blockMeetsTriangle(i64vec2 v0, i64vec2 p1, i64vec2 p2, ivec2 corner) {
  return largestEdgeValue(v0, p1, corner) >= 0l && largestEdgeValue(p1, p2, corner) >= 0l &&
         largestEdgeValue(p2, v0, corner) >= 0l;
}
