#pragma once
// A block of triangles handed to a device whole (DepthStencilDevice::drawMesh), so that a device
// may draw only the triangles that can reach its scissor. The draw's meaning is exactly
// drawTriangles(allTriangles()): a device that draws less must write the same bits.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "recode/raster/state.hpp"
#include "recode/raster/vertex_stage.hpp"

namespace recode::raster {

// One indexed draw, as drawTriangles takes it. The spans stay valid while the source lives
// and until its next call.
struct TriangleDraw {
  std::span<const WindowVertex> vertices;
  std::span<const std::uint32_t> indices;
};

// A block's triangles before the vertex stage (vertex_stage.hpp): its object-space vertices,
// which a device may keep for as long as the mesh lives, and the pose and window mapping of one
// draw. Drawing it is drawTriangles of vertexStage(transform, v) for every vertex v, with these
// indices.
struct PosedMesh {
  std::span<const double> localXyz;        // x, y, z of each vertex, in the block's coordinates
  std::span<const std::uint32_t> indices;  // three a triangle, as allTriangles() gives them
  VertexTransform transform;
  // Names localXyz and indices (their values) for as long as `alive` has not expired, unique in
  // the process (newTriangleSourceKey): a device that kept a copy under this key may draw from
  // it instead of reading the spans again.
  std::uint64_t meshKey = 0;
  // Expires when the mesh is gone: a device lets its copy go then.
  std::weak_ptr<const void> alive;
};

class TriangleSource {
 public:
  virtual ~TriangleSource() = default;

  // The whole block: every vertex and every triangle, in the block's order. May throw what
  // making its vertices throws (a vertex a view cannot map).
  [[nodiscard]] virtual TriangleDraw allTriangles() const = 0;

  // Optional: the block's triangles that can cover the centre of a pixel of `rect`, in the
  // block's order, each with the same window coordinates as in allTriangles() (the indices
  // may point into a different vertex array). Leaving out only triangles that cover no pixel
  // centre of `rect` makes drawing these under a scissor inside `rect` write exactly what
  // drawing allTriangles() writes. nullopt when the source cannot tell, or when
  // allTriangles() would throw or give a draw that drawTriangles refuses (so that the refusal
  // stays the full draw's); otherwise the draw it gives is valid.
  [[nodiscard]] virtual std::optional<TriangleDraw> trianglesMeeting(const PixelRect& rect) const {
    (void)rect;
    return std::nullopt;
  }

  // Optional: a number that names this source's triangles for as long as it lives, unique in
  // the process (newTriangleSourceKey). A source that returns one promises that every draw it
  // gives, whole or met, has the same triangles with the same window coordinates each time it is
  // asked, so a device may keep what one draw of it rasterized for the next (CpuDevice does:
  // raster/draw_recording.hpp). 0, the default, promises nothing.
  [[nodiscard]] virtual std::uint64_t contentKey() const { return 0; }

  // Optional: the block before the vertex stage, when the source knows that every vertex it
  // lists maps to a position a draw takes (raster::drawablePosition), so that a device running
  // the stage has nothing to refuse. Then allTriangles() is, bit for bit, the vertex stage of
  // localXyz with the same indices. nullopt, the default: the source offers window vertices
  // only.
  [[nodiscard]] virtual std::optional<PosedMesh> posedMesh() const { return std::nullopt; }
};

// What a device that draws only what meets its scissor draws of `source`:
// trianglesMeeting(scissor) when the source can tell, else allTriangles(). The triangles left
// out cover no pixel centre inside the scissor, so the bits are those of the whole draw; a source
// that cannot tell (or whose full draw would be refused) is drawn whole, so its refusal is the
// full draw's.
[[nodiscard]] inline TriangleDraw trianglesToDraw(const TriangleSource& source,
                                                  const PixelRect& scissor) {
  const std::optional<TriangleDraw> near = source.trianglesMeeting(scissor);
  return near ? *near : source.allTriangles();
}

// A key no other call in this process returns (never 0), for TriangleSource::contentKey.
[[nodiscard]] std::uint64_t newTriangleSourceKey();

}  // namespace recode::raster
