#version 450
#extension GL_GOOGLE_include_directive : require
// The compute device's read-backs and summary inputs: the rectangle in Draw.scissor copied out
// of the framebuffer, rows from the bottom, into Output from word Draw.outWord on. Draw's
// triangleCount is the form: 0 the depth q a word, 1 the stencil a byte (four a word, the last
// word padded with zeros), 2 the depth as the float q 2^-24 a word (what the summary shader and
// the other Vulkan device's copies hold; exact, since q < 2^24).

layout(local_size_x = 64) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) readonly buffer Framebuffer { uint pixels[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Output { uint words[]; };

uint pixelAt(uint k, uint rectWidth) {
  const uint x = uint(draw.scissor.x) + k % rectWidth;
  const uint y = uint(draw.scissor.y) + k / rectWidth;
  return pixels[y * draw.width + x];
}

void main() {
  const uint rectWidth = uint(draw.scissor.z - draw.scissor.x);
  const uint count = rectWidth * uint(draw.scissor.w - draw.scissor.y);
  const uint k = linearInvocation();
  if (draw.triangleCount == 1u) {
    const uint first = 4u * k;
    if (first >= count)
      return;
    uint word = 0u;
    for (uint b = 0u; b < 4u && first + b < count; ++b)
      word |= stencilOf(pixelAt(first + b, rectWidth)) << (8u * b);
    words[draw.outWord + k] = word;
    return;
  }
  if (k >= count)
    return;
  const uint q = depthOf(pixelAt(k, rectWidth));
  words[draw.outWord + k] = draw.triangleCount == 0u ? q : floatBitsToUint(float(q) * (1.0 / 16777216.0));
}
