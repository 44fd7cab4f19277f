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
