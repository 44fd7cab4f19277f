#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// tile_scan.comp's prefix sum in one invocation, for CPU drivers: there a workgroup with
// barriers runs its invocations as coroutines, which costs more than adding a few thousand
// counts in a row (the device picks it on lavapipe for up to kMostSerialScanJobs jobs; a GPU,
// and lavapipe past that, runs tile_scan.comp). llvmpipe ends a shader's loops after 65,535
// iterations in all (its guard against endless loops), so a longer serial loop would stop
// short without a word.

layout(local_size_x = 1) in;

#include "tile_common.glsl"

layout(std430, set = 0, binding = 7) readonly buffer BinEntries { uint binEntries[]; };
layout(std430, set = 0, binding = 8) writeonly buffer BinOffsets { uint binOffsets[]; };
layout(std430, set = 0, binding = 9) writeonly buffer BinCursors { uint binCursors[]; };

void main() {
  const uint jobs = frame.jobCount;
  uint offset = 0u;
  for (uint j = 0u; j < jobs; ++j) {
    binOffsets[j] = offset;
    binCursors[j] = offset;
    offset += binEntries[j];
  }
}
