// The frame's records as the stages bind them (tile_common.glsl defines each; a stage includes
// this after it and uses what it needs). Every record array is read-only: the host wrote them.

layout(std430, set = 0, binding = 0) readonly buffer Targets { Target targets[]; };
layout(std430, set = 0, binding = 1) readonly buffer Epochs { Epoch epochs[]; };
layout(std430, set = 0, binding = 2) readonly buffer Commands { Command commands[]; };
layout(std430, set = 0, binding = 3) readonly buffer Draws { DrawSource draws[]; };

// The draw that holds frame triangle t: the last whose firstTriangle <= t (t < triangleCount).
uint drawOfTriangle(uint t) {
  uint found;
  LAST_AT_OR_BELOW(found, draws, firstTriangle, frame.drawCount, t);
  return found;
}

// The epoch that holds job j: the last whose firstJob <= j (j < jobCount).
uint epochOfJob(uint j) {
  uint found;
  LAST_AT_OR_BELOW(found, epochs, firstJob, frame.epochCount, j);
  return found;
}

// The block of epoch e's grid that holds pixel (x, y) (inside the grid).
uvec2 blockOf(Epoch e, int x, int y) {
  return uvec2(uint(x - e.gridOrigin.x) >> 3, uint(y - e.gridOrigin.y) >> 3);
}
