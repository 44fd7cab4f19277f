#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's resolve stage, one invocation a pixel of every ResolveRange: the pixel's value at
// the end of the frame is the one the last epoch of its target whose footprint holds it left
// in JobFinal. An epoch that stored its pixels itself (kEpochStores) meets no other, so when it
// is the one found, there is nothing to do; when none is, nothing touched the pixel.

layout(local_size_x = 64) in;

#include "tile_common.glsl"
#include "tile_frame_inputs.glsl"

layout(std430, set = 0, binding = 11) readonly buffer JobFinal { uint jobFinal[]; };
layout(std430, set = 0, binding = 13) readonly buffer ResolveRanges { ResolveRange ranges[]; };

uint rangeOfPixel(uint i) {
  uint low = 0u;
  uint high = frame.resolveRanges;
  while (high - low > 1u) {
    const uint middle = (low + high) / 2u;
    if (ranges[middle].firstPixel <= i)
      low = middle;
    else
      high = middle;
  }
  return low;
}

void main() {
  const uint i = linearInvocation();
  if (i >= frame.resolvePixels)
    return;
  const ResolveRange range = ranges[rangeOfPixel(i)];
  const uint k = i - range.firstPixel;
  const uint rectWidth = uint(range.rect.z - range.rect.x);
  const int x = range.rect.x + int(k % rectWidth);
  const int y = range.rect.y + int(k / rectWidth);
  for (uint e = range.epochEnd; e > range.firstEpoch; --e) {
    const Epoch epoch = epochs[e - 1u];
    if (!insideRect(epoch.footprint, x, y))
      continue;
    if ((epoch.flags & kEpochStores) == 0u) {
      const uvec2 block = blockOf(epoch, x, y);
      const uint slot = epoch.firstFinal + block.y * epoch.gridWidth + block.x;
      const Target target = targets[range.target];
      PixelWords framebuffer = PixelWords(target.pixels);
      framebuffer.pixels[uint(y) * target.width + uint(x)] =
          jobFinal[slot * 64u + uint(y - epoch.gridOrigin.y - int(block.y) * 8) * 8u +
                   uint(x - epoch.gridOrigin.x - int(block.x) * 8)];
    }
    return;
  }
}
