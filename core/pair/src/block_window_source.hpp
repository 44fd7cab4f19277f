#pragma once
// A block as the device draws it (raster::TriangleSource), private to collidePair: its window
// vertices are made from the view once, and when the block can be drawn culled, only for the
// triangles a draw's rectangle needs.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "recode/pair/pair_block.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/triangle_source.hpp"

namespace recode::core::detail {

class BlockWindowSource final : public raster::TriangleSource {
 public:
  // Maps every vertex now, throwing as OrthoView::toWindow does, unless the block can be drawn
  // culled: drawable, with a hierarchy, and the two extreme corners of its box map inside the
  // view's range. The view maps each coordinate monotonically, so every vertex then maps
  // inside it too (nothing can throw later), and a vertex is mapped only when a draw needs it.
  BlockWindowSource(const PairBlock& block, const OrthoView& view);

  // Window vertices whose box is the box of all the block's window vertices (x, y and
  // quantised depth): all of them, or the images of the world box's two extreme corners,
  // which by monotonicity are the same extremes bit for bit.
  [[nodiscard]] std::span<const raster::WindowVertex> extremes() const;

  [[nodiscard]] bool culls() const { return culls_; }

  [[nodiscard]] raster::TriangleDraw allTriangles() const override;
  [[nodiscard]] std::optional<raster::TriangleDraw> trianglesMeeting(
      const raster::PixelRect& rect) const override;

 private:
  void gather(const raster::PixelRect& rect) const;

  const PairBlock& block_;
  const OrthoView& view_;
  bool culls_ = false;
  std::array<raster::WindowVertex, 2> corners_{};
  // The whole block, made on first use.
  mutable bool allMade_ = false;
  mutable std::vector<raster::WindowVertex> all_;
  mutable std::vector<std::uint32_t> allIndices_;
  // The last culled draw and its rectangle (the passes ask for one rectangle several times).
  mutable std::optional<raster::PixelRect> nearRect_;
  mutable std::vector<std::uint32_t> candidates_;
  mutable std::vector<raster::WindowVertex> near_;
  mutable std::vector<std::uint32_t> nearIndices_;
};

}  // namespace recode::core::detail
