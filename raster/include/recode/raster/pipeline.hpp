#pragma once
// The raster pipeline as one stateless function over a RenderState: for each triangle of an
// indexed draw, snap the vertices (fixed_point.hpp), set it up (triangle_setup.hpp), cull it by
// its snapped facing, and traverse its covered pixels inside the scissor (traversal.hpp); the
// fragments go to a sink. CpuDevice's sink runs the fragment stage (fragment_stage.hpp) on its
// buffers; the GL parity comparer's sink re-runs it on the reference's values to find the depth
// tests GL could decide the other way. Both therefore see the same triangles, in the same order,
// with the same coverage: the stages exist once.

#include <array>
#include <cstdint>
#include <span>

#include "recode/raster/device.hpp"
#include "recode/raster/state.hpp"
#include "recode/raster/traversal.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::raster {

// Receives each triangle that survives setup and culling, then its covered 8x8 blocks
// (BlockSink::coveredBlock, inside the state's scissor), before the next triangle.
class TriangleSink : public BlockSink {
 public:
  virtual void beginTriangle(const TriangleSetup& triangle,
                             const std::array<FixedVertex, 3>& snapped) = 0;
};

struct PipelineCounters {
  std::uint64_t trianglesSubmitted = 0;
  std::uint64_t trianglesDegenerate = 0;  // zero area after snapping: nothing drawn
  std::uint64_t trianglesCulled = 0;
  TraversalStats traversal;
};

// Draws indexed triangles (three indices each) under `state`. The draw must already be valid
// (checkDraw in device_checks.hpp: indices in range, vertices finite and within range); that is
// the device's job, so that a bad draw is refused before any pixel changes.
void drawTriangles(const RenderState& state, std::span<const WindowVertex> vertices,
                   std::span<const std::uint32_t> indices, TriangleSink& sink,
                   PipelineCounters* counters = nullptr);

}  // namespace recode::raster
