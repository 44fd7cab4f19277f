// The exact GL device's pixel summaries: the buffers of backends/exact/shaders/pixel_summary.glsl,
// which the device appends to this stage (after "#version 450 core"), one summary a dispatch.

layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer NearScratch { uint nearWords[]; };
layout(std430, binding = 1) readonly buffer Scratch { uint words[]; };
layout(std430, binding = 2) writeonly buffer Results { uint results[]; };
layout(std430, binding = 3) readonly buffer Summaries { uint parameters[]; };

void summarize(uint base);  // pixel_summary.glsl, below

void main() {
  summarize(0u);
}
