#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's set-up stage, one invocation a triangle of every draw of the frame: snaps the three
// window vertices (section 2 of docs/rasterization.md), takes the doubled area, the facing and
// the culling (section 3), clips the candidate pixels to the draw's scissor and sets up the depth
// plane (section 5, exact_contract.glsl: every operation `precise`, the division correctly
// rounded). The binning stage then lists the triangle in the jobs it may cover a centre of
// (tile_scatter.comp).

layout(local_size_x = 64) in;

#include "exact_contract.glsl"
#include "tile_common.glsl"
#include "tile_frame_inputs.glsl"

layout(std430, set = 0, binding = 6) writeonly buffer Triangles { SetUpTriangle triangles[]; };

FloatWords vertexData;

// The snapped position of vertex v: nearbyint(x 256), in double, round half to even.
i64vec2 snapped(uint v) {
  precise double x = double(vertexData.values[3u * v]) * 256.0;
  precise double y = double(vertexData.values[3u * v + 1u]) * 256.0;
  return i64vec2(roundToNearestEven(x), roundToNearestEven(y));
}

// Triangle t draws nothing: its candidates empty, its other words never read.
void writeEmpty(uint t) {
  for (uint k = 0u; k < 4u; ++k)
    triangles[t].candidates[k] = 0;
}

void main() {
  const uint t = linearInvocation();
  if (t >= frame.triangleCount)
    return;
  const DrawSource source = draws[drawOfTriangle(t)];
  const Command command = commands[source.command];
  vertexData = FloatWords(source.vertices);
  IndexWords indexData = IndexWords(source.indices);
  const uint local = t - source.firstTriangle;
  const uint i0 = indexData.indices[3u * local];
  const uint i1 = indexData.indices[3u * local + 1u];
  const uint i2 = indexData.indices[3u * local + 2u];
  const i64vec2 v0 = snapped(i0);
  const i64vec2 v1 = snapped(i1);
  const i64vec2 v2 = snapped(i2);
  const int64_t area = twiceArea(v0, v1, v2);
  const bool front = area > 0l;
  const uint cull = cullModeOf(command);
  if (area == 0l || (cull == 1u && front) || (cull == 2u && !front)) {
    writeEmpty(t);
    return;
  }
  // Pixels whose centres (256 i + 128) lie in the snapped bounding box, then the scissor.
  const ivec4 scissor = command.rect;
  const int64_t minX = min(v0.x, min(v1.x, v2.x));
  const int64_t maxX = max(v0.x, max(v1.x, v2.x));
  const int64_t minY = min(v0.y, min(v1.y, v2.y));
  const int64_t maxY = max(v0.y, max(v1.y, v2.y));
  const int x0 = max(int((minX + 127l) >> 8), scissor.x);
  const int x1 = min(int(((maxX - 128l) >> 8) + 1l), scissor.z);
  const int y0 = max(int((minY + 127l) >> 8), scissor.y);
  const int y1 = min(int(((maxY - 128l) >> 8) + 1l), scissor.w);
  if (x0 >= x1 || y0 >= y1) {
    writeEmpty(t);
    return;
  }
  triangles[t].x0 = int(v0.x);
  triangles[t].y0 = int(v0.y);
  triangles[t].x1 = int(v1.x);
  triangles[t].y1 = int(v1.y);
  triangles[t].x2 = int(v2.x);
  triangles[t].y2 = int(v2.y);
  triangles[t].front = front ? 1u : 0u;
  triangles[t].candidates[0] = x0;
  triangles[t].candidates[1] = y0;
  triangles[t].candidates[2] = x1;
  triangles[t].candidates[3] = y1;
  const vec3 z = vec3(vertexData.values[3u * i0 + 2u], vertexData.values[3u * i1 + 2u],
                      vertexData.values[3u * i2 + 2u]);
  const dvec2 slopes = depthSlopes(v0, v1, v2, z);
  triangles[t].z0 = floatBitsToUint(z.x);
  triangles[t].dzdx = unpackDouble2x32(slopes.x);
  triangles[t].dzdy = unpackDouble2x32(slopes.y);
}
