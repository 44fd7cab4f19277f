// BlockWindowSource (the block as collidePair hands it to the device, private to the pair
// layer): which triangles a culled draw of a rectangle lists, and in which order. The draw
// must list, in the block's order, the triangles that can cover a pixel centre of the
// rectangle; a block mostly inside the rectangle keeps every triangle whose snapped box holds
// one, any other block only those that cover one under the fill rule.

#include <catch2/catch.hpp>

#include <array>
#include <optional>
#include <vector>

#include "block_window_source.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/pair/view.hpp"

using namespace recode;
using raster::PixelRect;
using raster::WindowVertex;

namespace {

// Seen along z over [0, 16] x [0, 16] at 16 x 16: window x and y are world x and y (the
// scale is 1 and a power of two, so nothing is rounded but the snapping to 1/256 pixel).
core::OrthoView view16() {
  return core::OrthoView(core::ViewAxis::Z, core::ViewWindow{0, 0, 16, 16}, 16, 16, -1.0, 1.0);
}

// Appends the triangle (a, b, c) with three vertices of its own; returns its index.
std::size_t addTriangle(core::TriangleMesh& mesh, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const auto first = static_cast<core::VertexIndex>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
  mesh.triangles.push_back({first, first + 1, first + 2});
  return mesh.triangles.size() - 1;
}

using WindowTriangle = std::array<std::array<float, 3>, 3>;

WindowTriangle windowTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c) {
  return {{{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}}};
}

// The triangles a draw lists, in its order.
std::vector<WindowTriangle> listed(const raster::TriangleDraw& draw) {
  std::vector<WindowTriangle> out;
  for (std::size_t k = 0; k + 2 < draw.indices.size(); k += 3)
    out.push_back(windowTriangle(draw.vertices[draw.indices[k]], draw.vertices[draw.indices[k + 1]],
                                 draw.vertices[draw.indices[k + 2]]));
  return out;
}

// The block's triangles `ids`, mapped by the view as a whole draw maps them.
std::vector<WindowTriangle> expected(const core::TriangleMesh& mesh, const core::OrthoView& view,
                                     const std::vector<std::size_t>& ids) {
  std::vector<WindowTriangle> out;
  for (const std::size_t t : ids) {
    const core::Triangle& tri = mesh.triangles[t];
    out.push_back(windowTriangle(view.toWindow(mesh.vertices[tri[0]]),
                                 view.toWindow(mesh.vertices[tri[1]]),
                                 view.toWindow(mesh.vertices[tri[2]])));
  }
  return out;
}

std::vector<WindowTriangle> drawn(const core::detail::BlockWindowSource& source,
                                  const PixelRect& rect) {
  const std::optional<raster::TriangleDraw> draw = source.trianglesMeeting(rect);
  REQUIRE(draw);
  return listed(*draw);
}

}  // namespace

TEST_CASE("a culled draw leaves out a triangle whose box holds a centre it does not cover") {
  // The rectangle holds pixels 2 and 3 each way (centres 2.5 and 3.5); the block reaches to 15,
  // so its window box (13 x 13) lies mostly outside (2 x 2 inside): the coverage test decides.
  // The sliver (2, 2), (2.9, 2), (2, 2.9) has a box that holds the centre (2.5, 2.5), but its
  // long edge x + y = 4.9 passes below it (2.5 + 2.5 = 5): only that one edge leaves it out,
  // so every rotation of its vertices is tried, putting that edge at each place.
  const core::OrthoView view = view16();
  const Eigen::Vector3d sliver[3] = {{2.0, 2.0, 0.0}, {2.9, 2.0, 0.0}, {2.0, 2.9, 0.0}};
  for (int rotation = 0; rotation < 3; ++rotation) {
    CAPTURE(rotation);
    core::TriangleMesh mesh;
    addTriangle(mesh, {12, 12, 0}, {15, 12, 0}, {15, 15, 0});  // far off, in the block's box
    addTriangle(mesh, sliver[rotation], sliver[(rotation + 1) % 3], sliver[(rotation + 2) % 3]);
    // Covers (2.5, 3.5): its long edge x + y = 6.9 passes above that centre's 6.
    const std::size_t covering =
        addTriangle(mesh, {2.0, 3.0, 0.0}, {3.9, 3.0, 0.0}, {2.0, 3.9, 0.0});
    const core::PairBlock block = core::PairBlock::withHierarchy(mesh);
    const core::detail::BlockWindowSource source(block, view);
    REQUIRE(source.culls());
    CHECK(drawn(source, PixelRect{2, 2, 4, 4}) == expected(mesh, view, {covering}));
  }
}

TEST_CASE("a culled draw of another rectangle lists that rectangle's triangles") {
  // The same block asked for two rectangles apart, then the first again: each draw is the
  // triangles of its own rectangle, not those of the draw before.
  const core::OrthoView view = view16();
  core::TriangleMesh mesh;
  const std::size_t far = addTriangle(mesh, {12, 12, 0}, {15, 12, 0}, {15, 15, 0});
  const std::size_t near = addTriangle(mesh, {2.0, 3.0, 0.0}, {3.9, 3.0, 0.0}, {2.0, 3.9, 0.0});
  const core::PairBlock block = core::PairBlock::withHierarchy(mesh);
  const core::detail::BlockWindowSource source(block, view);
  REQUIRE(source.culls());
  CHECK(drawn(source, PixelRect{2, 2, 4, 4}) == expected(mesh, view, {near}));
  CHECK(drawn(source, PixelRect{12, 12, 16, 16}) == expected(mesh, view, {far}));
  CHECK(drawn(source, PixelRect{2, 2, 4, 4}) == expected(mesh, view, {near}));
}

TEST_CASE("a culled draw lists its triangles in the block's order, not the hierarchy's") {
  // Sixteen small triangles in a row, triangle i over the centre (15 - i + 0.5, 1.5) (its
  // long edge x' + y' = 1.25 from its corner at (15 - i, 1) passes beyond the centre's 1): the
  // hierarchy (leaves of four, split at the median, visited low half first) holds them left to
  // right, the block right to left. The rectangle over columns 0..5 meets triangles 15..10, in
  // two leaves; the block's box (15.75 x 0.75) is mostly outside it (5.75 x 0.75 inside), so
  // the hierarchy is queried.
  const core::OrthoView view = view16();
  core::TriangleMesh mesh;
  for (int i = 0; i < 16; ++i) {
    const double p = 15 - i;
    addTriangle(mesh, {p + 0.25, 1.25, 0.0}, {p + 1.0, 1.25, 0.0}, {p + 0.25, 2.0, 0.0});
  }
  const core::PairBlock block = core::PairBlock::withHierarchy(mesh);
  const core::detail::BlockWindowSource source(block, view);
  REQUIRE(source.culls());
  CHECK(drawn(source, PixelRect{0, 0, 6, 16}) == expected(mesh, view, {10, 11, 12, 13, 14, 15}));
}

TEST_CASE("a block mostly inside the rectangle keeps every triangle whose box holds a centre") {
  // Rectangle: x in 0..7, y in 0..3 (centres up to 3.5). The block's box is x in [1, 4.9],
  // y in [1, 5.4]: 3.9 x 4.4 = 17.16, of which 3.9 x 3 = 11.7 (at least half) is inside, so
  // its triangles are kept by their snapped boxes alone, without the coverage test.
  const core::OrthoView view = view16();
  core::TriangleMesh mesh;
  const std::size_t covering = addTriangle(mesh, {1, 1, 0}, {3, 1, 0}, {1, 3, 0});
  // Its box holds the centre (4.5, 2.5), which its long edge x + y = 6.9 (< 7) leaves out:
  // kept all the same.
  const std::size_t boxOnly = addTriangle(mesh, {4.0, 2.0, 0.0}, {4.9, 2.0, 0.0}, {4.0, 2.9, 0.0});
  // Its x range holds centres of the rectangle, its y range [4.6, 5.4] none (not even 4.5 or
  // 5.5, and the rectangle's end at 4 anyway): left out.
  addTriangle(mesh, {1.0, 4.6, 0.0}, {2.9, 4.6, 0.0}, {1.0, 5.4, 0.0});
  const core::PairBlock block = core::PairBlock::withHierarchy(mesh);
  const core::detail::BlockWindowSource source(block, view);
  REQUIRE(source.culls());
  CHECK(drawn(source, PixelRect{0, 0, 8, 4}) == expected(mesh, view, {covering, boxOnly}));
}

TEST_CASE("a block seen edge-on is drawn culled as no triangles") {
  // A flat block in the plane x = 2.5 (or y = 2.5), seen along z: its window box has no width
  // (or no height), so no part of its area lies inside the rectangle and the coverage test
  // decides; its triangles have no area after snapping and cover nothing. (Their snapped boxes
  // do hold centres: 2.5 is the centre of pixel 2.)
  const core::OrthoView view = view16();
  for (const int flat : {0, 1}) {
    CAPTURE(flat);
    const auto at = [flat](double along, double z) {
      return flat == 0 ? Eigen::Vector3d(2.5, along, z) : Eigen::Vector3d(along, 2.5, z);
    };
    core::TriangleMesh mesh;
    addTriangle(mesh, at(2, 0), at(5, 0), at(5, 0.5));
    addTriangle(mesh, at(2, 0), at(5, 0.5), at(2, 0.5));
    const core::PairBlock block = core::PairBlock::withHierarchy(mesh);
    const core::detail::BlockWindowSource source(block, view);
    REQUIRE(source.culls());
    CHECK(drawn(source, PixelRect{0, 0, 8, 8}).empty());
  }
}

TEST_CASE("a culled draw of a rectangle inside the last one keeps the triangles covering it") {
  // The block reaches from 1 to 15 each way, so its window box (14 x 14) lies mostly outside
  // the first rectangle (pixels 0..7 each way, 7 x 7 inside): the hierarchy is queried with the
  // coverage test. The second rectangle (pixels 2 and 3 each way, centres 2.5 and 3.5) lies
  // inside the first, so its draw is filtered from the first's triangles.
  const core::OrthoView view = view16();
  core::TriangleMesh mesh;
  // Covers (2.5, 2.5): its long edge x + y = 5.9 passes above that centre's 5.
  const std::size_t covering = addTriangle(mesh, {2.0, 2.0, 0.0}, {3.9, 2.0, 0.0}, {2.0, 3.9, 0.0});
  // Covers (1.5, 1.5) (sum 3 < 3.9), a centre of the first rectangle only: its box holds the
  // second's centre (2.5, 2.5), which its long edge x + y = 3.9 leaves out.
  const std::size_t outside = addTriangle(mesh, {1.0, 1.0, 0.0}, {2.9, 1.0, 0.0}, {1.0, 2.9, 0.0});
  // Covers (5.5, 5.5): inside the first rectangle, its box far from the second.
  const std::size_t apart = addTriangle(mesh, {5.0, 5.0, 0.0}, {7.0, 5.0, 0.0}, {5.0, 7.0, 0.0});
  addTriangle(mesh, {12, 12, 0}, {15, 12, 0}, {15, 15, 0});  // outside both rectangles
  const core::PairBlock block = core::PairBlock::withHierarchy(mesh);
  const core::detail::BlockWindowSource source(block, view);
  REQUIRE(source.culls());
  CHECK(drawn(source, PixelRect{0, 0, 8, 8}) == expected(mesh, view, {covering, outside, apart}));
  CHECK(drawn(source, PixelRect{2, 2, 4, 4}) == expected(mesh, view, {covering}));
}
