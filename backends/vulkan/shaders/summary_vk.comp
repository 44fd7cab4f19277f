#version 450
#extension GL_GOOGLE_include_directive : require
// The Vulkan devices' pixel summaries (backends/exact/shaders/pixel_summary.glsl): the
// summaries recorded since the last submission, one workgroup each, in one dispatch recorded
// just before the submission (one per set of buffers); workgroup k makes the k-th summary from
// `firstWord` on.

layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 0) readonly buffer NearScratch { uint nearWords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Scratch { uint words[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Results { uint results[]; };
layout(std430, set = 0, binding = 3) readonly buffer Summaries { uint parameters[]; };

layout(push_constant) uniform Dispatch { uint firstWord; } dispatch;

#include "pixel_summary.glsl"

void main() {
  summarize(dispatch.firstWord + 13u * gl_WorkGroupID.x);
}
