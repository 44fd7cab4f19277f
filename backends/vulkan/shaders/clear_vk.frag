#version 450
// The clear pipeline's fragment stage: every pixel gets the clear depth, q 2^-24 for the
// contract's quantised q, exact in float. Whether it is written is fixed-function state (depth
// test ALWAYS, depth write as the device's mask says; off for a stencil clear).

layout(push_constant) uniform Frame {
  vec2 framebufferSize;
  float clearDepth;
} frame;

void main() {
  gl_FragDepth = frame.clearDepth;
}
