// The triangle hierarchy against brute force: every triangle whose own box meets a query box is
// collected, in increasing order, once; a query meeting nothing collects nothing.

#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <stdexcept>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/triangle_bvh.hpp"

using namespace recode;

namespace {

bool boxesMeet(const core::Aabb& a, const core::Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

core::Aabb triangleBox(const core::TriangleMesh& mesh, std::size_t t) {
  core::Aabb box;
  for (core::VertexIndex i : mesh.triangles[t])
    box.extend(mesh.vertices[i]);
  return box;
}

}  // namespace

TEST_CASE("triangle hierarchy: random boxes collect every triangle brute force finds, in order") {
  const core::TriangleMesh mesh = core::makeSphere(1.0, 48, 24);
  const core::TriangleBvh bvh(mesh);
  REQUIRE(bvh.triangleCount() == mesh.triangleCount());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> centre(-1.2, 1.2), size(0.0, 0.4);
  int nonEmpty = 0;
  for (int q = 0; q < 300; ++q) {
    core::Aabb query;
    const Eigen::Vector3d c(centre(rng), centre(rng), centre(rng));
    const Eigen::Vector3d h(size(rng), size(rng), size(rng));
    query.extend(Eigen::Vector3d(c - h));
    query.extend(Eigen::Vector3d(c + h));
    std::vector<std::uint32_t> got;
    bvh.collect([&](const core::Aabb& box) { return boxesMeet(box, query); }, got);
    CHECK(std::adjacent_find(got.begin(), got.end(), std::greater_equal<>()) == got.end());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
      if (boxesMeet(triangleBox(mesh, t), query)) {
        INFO("query " << q << ", triangle " << t);
        CHECK(std::binary_search(got.begin(), got.end(), static_cast<std::uint32_t>(t)));
      }
    nonEmpty += got.empty() ? 0 : 1;
  }
  CHECK(nonEmpty > 50);  // the queries did reach the surface
}

TEST_CASE("triangle hierarchy: a query meeting everything gives every triangle, nothing none") {
  const core::TriangleMesh mesh = core::makeSphere(1.0, 16, 8);
  const core::TriangleBvh bvh(mesh);
  std::vector<std::uint32_t> all, none;
  bvh.collect([](const core::Aabb&) { return true; }, all);
  bvh.collect([](const core::Aabb&) { return false; }, none);
  REQUIRE(all.size() == mesh.triangleCount());
  for (std::size_t t = 0; t < all.size(); ++t)
    CHECK(all[t] == t);
  CHECK(none.empty());
}

TEST_CASE("triangle hierarchy: a triangle index out of range is refused") {
  core::TriangleMesh mesh = core::makeSphere(1.0, 8, 4);
  mesh.triangles[5][1] = static_cast<core::VertexIndex>(mesh.vertexCount());
  CHECK_THROWS_AS(core::TriangleBvh(mesh), std::out_of_range);
}

TEST_CASE("sortDistinctIds: sparse and dense sets of ids come out as std::sort orders them") {
  // Both ways of sorting (a comparison sort for a few ids in a large range, a bit per id for
  // many): counts from none to all of the range, ranges from 1 to 1,000,000, and ids at the
  // range's ends; the scratch is reused dirty from one call to the next.
  std::mt19937 rng(7);
  std::vector<std::uint64_t> bits;
  int sparse = 0, dense = 0;
  for (const std::size_t range : {1u, 63u, 64u, 65u, 1000u, 200000u, 1000000u}) {
    for (const double fraction : {0.0, 0.0001, 0.01, 0.3, 1.0}) {
      std::vector<std::uint32_t> all(range);
      for (std::size_t i = 0; i < range; ++i)
        all[i] = static_cast<std::uint32_t>(i);
      std::shuffle(all.begin(), all.end(), rng);
      const auto count = static_cast<std::size_t>(fraction * static_cast<double>(range));
      std::vector<std::uint32_t> ids(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(count));
      if (count >= 2) {  // make sure the range's first and last ids are in the set
        ids[0] = 0;
        ids[1] = static_cast<std::uint32_t>(range - 1);
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        std::shuffle(ids.begin(), ids.end(), rng);
      }
      std::vector<std::uint32_t> expected = ids;
      std::sort(expected.begin(), expected.end());
      if (!ids.empty())
        (ids.size() * 16 < (range + 63) / 64 ? sparse : dense) += 1;
      core::sortDistinctIds(ids, range, bits);
      // The first difference, not the vectors: Catch would print a million ids.
      const auto diff = std::mismatch(ids.begin(), ids.end(), expected.begin());
      INFO("range " << range << ", " << expected.size() << " ids, first difference at "
                    << (diff.first - ids.begin()));
      CHECK(diff.first == ids.end());
    }
  }
  CHECK(sparse == 2);  // both ways were taken: 20 of 200,000 and 100 of 1,000,000 ids
  CHECK(dense == 16);
}
