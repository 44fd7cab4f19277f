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
  // The block and the view are fixed for the source's life, so its draws are too: a device may
  // replay the first for the next (raster::DrawRecording).
  [[nodiscard]] std::uint64_t contentKey() const override { return key_; }
  // The block's object-space mesh with its pose and the view's mapping, when the block has one
  // (PairBlock::objectSpaceMesh) and can be drawn culled: then every vertex maps inside the
  // view's range (the box corners do, and the mapping is monotonic).
  [[nodiscard]] std::optional<raster::PosedMesh> posedMesh() const override;

 private:
  // Queries the hierarchy for `rect`: the base list every smaller rectangle is filtered from.
  void gather(const raster::PixelRect& rect) const;
  // The base triangles whose box holds a pixel centre of `rect` (inside the base rectangle).
  void narrow(const raster::PixelRect& rect) const;
  // Whether at least half the block's window box (x and y) lies inside `rect`.
  [[nodiscard]] bool mostlyInside(const raster::PixelRect& rect) const;

  const PairBlock& block_;
  // A copy: a source outlives the scope that made its view (collidePairs draws a pair's contact
  // passes in a later round).
  const OrthoView view_;
  const std::uint64_t key_ = raster::newTriangleSourceKey();
  bool culls_ = false;
  std::array<raster::WindowVertex, 2> corners_{};
  // The whole block, made on first use.
  mutable bool allMade_ = false;
  mutable std::vector<raster::WindowVertex> all_;
  mutable std::vector<std::uint32_t> allIndices_;
  // The last hierarchy query (the MOR): its rectangle and triangles, three window vertices
  // each, in the block's order. A rectangle inside it (the contact rectangle) is served from
  // this list: a triangle that can cover a centre of the smaller one is in it.
  mutable std::optional<raster::PixelRect> baseRect_;
  mutable std::vector<raster::WindowVertex> base_;
  // The last draw handed out and its rectangle (the passes ask for one rectangle several
  // times); near_ is base_ itself when the rectangles are the same.
  mutable std::optional<raster::PixelRect> nearRect_;
  mutable std::vector<raster::WindowVertex> narrowed_;
  mutable std::span<const raster::WindowVertex> near_;
  mutable std::vector<std::uint32_t> sequence_;  // 0, 1, 2, ...: each triangle its own three
};

}  // namespace recode::core::detail
