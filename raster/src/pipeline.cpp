#include "recode/raster/pipeline.hpp"

#include "recode/raster/invariants.hpp"
#include "triangle_setup_steps.hpp"

namespace recode::raster {

void drawTriangles(const RenderState& state, std::span<const WindowVertex> vertices,
                   std::span<const std::uint32_t> indices, TriangleSink& sink,
                   PipelineCounters* counters) {
  RECODE_INVARIANT(indices.size() % 3 == 0, "a draw's index count is a multiple of three");
  RECODE_INVARIANT(state.scissor.x0 >= 0 && state.scissor.y0 >= 0 &&
                       state.scissor.x0 <= state.scissor.x1 && state.scissor.y0 <= state.scissor.y1,
                   "the scissor is clamped to the framebuffer");
  PipelineCounters local;
  PipelineCounters& count = counters != nullptr ? *counters : local;
  TriangleSetup triangle;  // every field rewritten for each triangle
  for (std::size_t k = 0; k + 2 < indices.size(); k += 3) {
    ++count.trianglesSubmitted;
    std::array<FixedVertex, 3> snapped;
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const std::uint32_t index = indices[k + corner];
      RECODE_INVARIANT(index < vertices.size(), "a draw's indices are in range");
      snapped[corner] = snapVertex(vertices[index]);
    }
    if (!detail::setupInto(snapped[0], snapped[1], snapped[2], triangle)) {
      ++count.trianglesDegenerate;
      continue;
    }
    if (state.culls(triangle.frontFacing)) {
      ++count.trianglesCulled;
      continue;
    }
    sink.beginTriangle(triangle, snapped);
    traverseTriangle(triangle, state.scissor, sink, &count.traversal);
  }
}

}  // namespace recode::raster
