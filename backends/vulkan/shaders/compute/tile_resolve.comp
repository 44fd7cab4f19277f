#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's resolve stage, one invocation a pixel of every ResolveRange (the footprint of an
// epoch that meets another epoch of its target): the pixel takes the value the epoch left in
// JobFinal unless a later epoch of the target holds the pixel too, whose own range then gives
// it. So each pixel is written once, by the last epoch that held it. (An epoch that meets no
// other stored its pixels itself, in the raster stage.) The host keeps a range's later epochs
// within a CPU driver's loop limit (tile_frame_budgets.hpp); an invocation whose loop ended
// before its end counts itself in Counters, which the host checks.

layout(local_size_x = 64) in;

#include "tile_common.glsl"
#include "tile_frame_inputs.glsl"

layout(std430, set = 0, binding = 11) readonly buffer JobFinal { uint jobFinal[]; };
layout(std430, set = 0, binding = 13) readonly buffer ResolveRanges { ResolveRange ranges[]; };
layout(std430, set = 0, binding = 16) readonly buffer LaterEpochs { uint laterEpochs[]; };
layout(std430, set = 0, binding = 19) buffer Counters { uint counters[]; };

uint rangeOfPixel(uint i) {
  uint found;
  LAST_AT_OR_BELOW(found, ranges, firstPixel, frame.resolveRanges, i);
  return found;
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
  const uint laterEnd = range.firstLater + range.laterCount;
  uint l = range.firstLater;
  for (; l < laterEnd; ++l)
    if (insideRect(epochs[laterEpochs[l]].footprint, x, y))
      return;
  if (l < laterEnd) {
    atomicAdd(counters[kCounterResolveShort], 1u);
    return;
  }
  const Epoch epoch = epochs[range.epoch];
  const uvec2 block = blockOf(epoch, x, y);
  const uint slot = epoch.firstFinal + block.y * epoch.gridWidth + block.x;
  const Target target = targets[range.target];
  PixelWords framebuffer = PixelWords(target.pixels);
  framebuffer.pixels[uint(y) * target.width + uint(x)] =
      jobFinal[pixelSlot(slot, uint(y - epoch.gridOrigin.y - int(block.y) * 8),
                         uint(x - epoch.gridOrigin.x - int(block.x) * 8))];
}
