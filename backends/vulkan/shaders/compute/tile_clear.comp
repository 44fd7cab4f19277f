#version 450
#extension GL_GOOGLE_include_directive : require
// The compute device's clears, one invocation a pixel of the scissor: a depth clear stores the
// quantised value in every pixel's depth (the host skips it while the depth write mask is off),
// a stencil clear (value & writeMask) | (s & ~writeMask), as GL's masked clear. Fields of Draw:
// triangleCount is the value (q, or the stencil byte), outWord 0 for depth and 1 for stencil.

layout(local_size_x = 8, local_size_y = 8) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) buffer Framebuffer { uint pixels[]; };

void main() {
  const ivec2 pixel = draw.scissor.xy + ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= draw.scissor.z || pixel.y >= draw.scissor.w)
    return;
  const uint at = uint(pixel.y) * draw.width + uint(pixel.x);
  const uint word = pixels[at];
  if (draw.outWord == 0u) {
    pixels[at] = packPixel(draw.triangleCount, stencilOf(word));
  } else {
    const uint writeMask = (draw.stencil >> 16) & 0xFFu;
    const uint s = stencilOf(word);
    pixels[at] = packPixel(depthOf(word), (draw.triangleCount & writeMask) | (s & ~writeMask));
  }
}
