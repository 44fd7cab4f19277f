#version 450
// The clear pipeline's vertex stage: one rectangle over the whole framebuffer; the scissor
// limits it to the clear's pixels, and the fixed-function depth and stencil write masks apply
// to it as they do to a draw (vkCmdClearAttachments would ignore them).

void main() {
  vec2 corner = vec2((gl_VertexIndex & 1) != 0 ? 1.0 : -1.0, (gl_VertexIndex & 2) != 0 ? 1.0 : -1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}
