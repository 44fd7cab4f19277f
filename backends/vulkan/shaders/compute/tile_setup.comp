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

layout(std430, set = 0, binding = 6) writeonly buffer Triangles { uint triangles[]; };

FloatWords vertexData;

// The snapped position of vertex v: nearbyint(x 256), in double, round half to even.
i64vec2 snapped(uint v) {
  precise double x = double(vertexData.values[3u * v]) * 256.0;
  precise double y = double(vertexData.values[3u * v + 1u]) * 256.0;
  return i64vec2(roundToNearestEven(x), roundToNearestEven(y));
}

void writeEmpty(uint base) {
  for (uint k = 0u; k < 4u; ++k)
    triangles[base + kTriangleCandidates + k] = 0u;
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
  const uint base = t * kWordsPerTriangle;
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
    writeEmpty(base);
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
    writeEmpty(base);
    return;
  }
  triangles[base + kTriangleX0 + 0u] = uint(int(v0.x));
  triangles[base + kTriangleX0 + 1u] = uint(int(v0.y));
  triangles[base + kTriangleX0 + 2u] = uint(int(v1.x));
  triangles[base + kTriangleX0 + 3u] = uint(int(v1.y));
  triangles[base + kTriangleX0 + 4u] = uint(int(v2.x));
  triangles[base + kTriangleX0 + 5u] = uint(int(v2.y));
  triangles[base + kTriangleFront] = front ? 1u : 0u;
  triangles[base + kTriangleCandidates + 0u] = uint(x0);
  triangles[base + kTriangleCandidates + 1u] = uint(y0);
  triangles[base + kTriangleCandidates + 2u] = uint(x1);
  triangles[base + kTriangleCandidates + 3u] = uint(y1);
  const vec3 z = vec3(vertexData.values[3u * i0 + 2u], vertexData.values[3u * i1 + 2u],
                      vertexData.values[3u * i2 + 2u]);
  const dvec2 slopes = depthSlopes(v0, v1, v2, z);
  triangles[base + kTriangleZ0] = floatBitsToUint(z.x);
  const uvec2 dzdx = unpackDouble2x32(slopes.x);
  const uvec2 dzdy = unpackDouble2x32(slopes.y);
  triangles[base + kTriangleSlopes + 0u] = dzdx.x;
  triangles[base + kTriangleSlopes + 1u] = dzdx.y;
  triangles[base + kTriangleSlopes + 2u] = dzdy.x;
  triangles[base + kTriangleSlopes + 3u] = dzdy.y;
}
