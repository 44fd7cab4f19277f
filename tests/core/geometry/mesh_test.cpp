// TriangleMesh helpers: bounding box, transformed copies (and transformInto), signed volume.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh.hpp"
#include "recode/geometry/validate.hpp"

using namespace recode::core;

TEST_CASE("Aabb starts empty and grows by points", "[mesh]") {
  Aabb box;
  CHECK(box.isEmpty());
  CHECK(box.diagonal() == 0.0);
  box.extend({1.0, -2.0, 3.0});
  CHECK_FALSE(box.isEmpty());
  CHECK(box.min == Eigen::Vector3d(1.0, -2.0, 3.0));
  CHECK(box.max == Eigen::Vector3d(1.0, -2.0, 3.0));
  CHECK(box.diagonal() == 0.0);
  box.extend({-1.0, 2.0, 3.0});
  CHECK(box.min == Eigen::Vector3d(-1.0, -2.0, 3.0));
  CHECK(box.max == Eigen::Vector3d(1.0, 2.0, 3.0));
  CHECK(box.extent() == Eigen::Vector3d(2.0, 4.0, 0.0));
  CHECK(box.center() == Eigen::Vector3d(0.0, 0.0, 3.0));
  CHECK(box.diagonal() == Approx(std::sqrt(20.0)));
}

TEST_CASE("boundingBox and counts of a mesh", "[mesh]") {
  const TriangleMesh box = makeBox(1.0, 2.0, 3.0);
  const Aabb aabb = boundingBox(box);
  CHECK(aabb.min == Eigen::Vector3d(-1.0, -2.0, -3.0));
  CHECK(aabb.max == Eigen::Vector3d(1.0, 2.0, 3.0));
  CHECK(box.vertexCount() == 8);
  CHECK(box.triangleCount() == 12);
  CHECK(boundingBox(TriangleMesh{}).isEmpty());

  const Aabb cone = boundingBox(makeCone(2.0, 5.0, 4));  // rim at +x, +y, -x, -y
  CHECK(cone.min.x() == -2.0);
  CHECK(cone.max.x() == 2.0);
  CHECK(cone.max.y() == Approx(2.0).epsilon(1e-15));
  CHECK(cone.min.z() == 0.0);
  CHECK(cone.max.z() == 5.0);
}

TEST_CASE("signedVolume of boxes and flipped meshes", "[mesh]") {
  TriangleMesh box = makeBox(1.0, 2.0, 3.0);
  CHECK(signedVolume(box) == Approx(48.0).epsilon(1e-15));
  for (Triangle& t : box.triangles) {
    std::swap(t[1], t[2]);
  }
  CHECK(signedVolume(box) == Approx(-48.0).epsilon(1e-15));
  // Far from the origin the volume stays accurate (computed about the box centre).
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(1e7, -3e7, 2e7);
  CHECK(signedVolume(transformed(makeBox(1.0, 1.0, 1.0), far)) == Approx(8.0).epsilon(1e-9));

  TriangleMesh broken = makeBox(1.0, 1.0, 1.0);
  broken.triangles[3][1] = 8;
  CHECK_THROWS_AS(signedVolume(broken), std::out_of_range);
}

TEST_CASE("transformed by an isometry moves vertices and keeps the mesh valid", "[mesh]") {
  const TriangleMesh cone = makeCone(1.0, 2.0, 16);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()));
  pose.pretranslate(Eigen::Vector3d(3.0, -1.0, 0.25));
  const TriangleMesh moved = transformed(cone, pose);

  REQUIRE(moved.vertexCount() == cone.vertexCount());
  CHECK(moved.triangles == cone.triangles);
  for (std::size_t i = 0; i < cone.vertexCount(); ++i) {
    CHECK((moved.vertices[i] - (pose.linear() * cone.vertices[i] + pose.translation())).norm() <
          1e-15);
  }
  // The apex (last vertex) goes to pose * (0, 0, 2).
  CHECK((moved.vertices.back() - pose * Eigen::Vector3d(0.0, 0.0, 2.0)).norm() < 1e-14);
  CHECK(signedVolume(moved) == Approx(signedVolume(cone)).epsilon(1e-12));
  CHECK_NOTHROW(validateConvexBlock(moved, "moved cone"));
}

TEST_CASE("transformed by an affine map scales volume and keeps faces outward", "[mesh]") {
  const TriangleMesh sphere = makeSphere(1.0, 12, 6);
  const double volume = signedVolume(sphere);

  Eigen::Affine3d stretch = Eigen::Affine3d::Identity();
  stretch.scale(Eigen::Vector3d(2.0, 3.0, 0.5));
  const TriangleMesh stretched = transformed(sphere, stretch);
  CHECK(stretched.triangles == sphere.triangles);
  CHECK(signedVolume(stretched) == Approx(3.0 * volume).epsilon(1e-12));

  // A reflection reverses the winding so that the faces still point outward.
  Eigen::Affine3d mirror = Eigen::Affine3d::Identity();
  mirror.scale(Eigen::Vector3d(-1.0, 1.0, 1.0));
  const TriangleMesh mirrored = transformed(sphere, mirror);
  REQUIRE(mirrored.triangleCount() == sphere.triangleCount());
  for (std::size_t t = 0; t < sphere.triangleCount(); ++t) {
    const Triangle& a = sphere.triangles[t];
    const Triangle& b = mirrored.triangles[t];
    CHECK(b == Triangle{a[0], a[2], a[1]});
  }
  CHECK(signedVolume(mirrored) == Approx(volume).epsilon(1e-12));
  CHECK_NOTHROW(validateConvexBlock(mirrored, "mirrored sphere"));
}

TEST_CASE("Aabb::extend by a box unites them, and an empty box adds nothing") {
  recode::core::Aabb a;
  a.extend(Eigen::Vector3d(0, 0, 0));
  a.extend(Eigen::Vector3d(1, 1, 1));
  recode::core::Aabb b;
  b.extend(Eigen::Vector3d(-1, 0.5, 2));
  a.extend(b);
  CHECK(a.min == Eigen::Vector3d(-1, 0, 0));
  CHECK(a.max == Eigen::Vector3d(1, 1, 2));
  a.extend(recode::core::Aabb{});
  CHECK(a.min == Eigen::Vector3d(-1, 0, 0));
  CHECK(a.max == Eigen::Vector3d(1, 1, 2));
  recode::core::Aabb empty;
  empty.extend(recode::core::Aabb{});
  CHECK(empty.isEmpty());
}

namespace {

bool sameBits(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Eigen::Vector3d)) == 0);
}

}  // namespace

TEST_CASE("transformInto writes transformed()'s mesh bit for bit into storage it reuses",
          "[mesh]") {
  const TriangleMesh cone = makeCone(1.0, 2.0, 16);
  Eigen::Isometry3d turned = Eigen::Isometry3d::Identity();
  turned.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()));
  turned.pretranslate(Eigen::Vector3d(3.0, -1.0, 0.25));
  Eigen::Isometry3d mirror = turned;
  mirror.linear() = turned.linear() * Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
  REQUIRE(mirror.linear().determinant() < 0.0);

  // Into a mesh that holds something else (another size), then the same storage pose after pose,
  // a reflection (the winding swapped) and back (swapped back).
  TriangleMesh out = makeSphere(1.0, 12, 6);
  for (const Eigen::Isometry3d& pose :
       {turned, mirror, Eigen::Isometry3d(turned.inverse()), mirror, turned}) {
    const TriangleMesh expected = transformed(cone, pose);
    const Eigen::Vector3d* storage = out.vertices.data();
    const std::size_t capacity = out.vertices.capacity();
    transformInto(cone, pose, out);
    CHECK(sameBits(out.vertices, expected.vertices));
    CHECK(out.triangles == expected.triangles);
    if (capacity >= cone.vertexCount())
      CHECK(out.vertices.data() == storage);  // no allocation once it fits
  }
}

TEST_CASE("drawableExtent: the largest coordinate of a drawable mesh, infinity for any other",
          "[mesh]") {
  TriangleMesh box = makeBox(1.0, 2.0, 3.0);  // half-sides: x in [-1, 1], z in [-3, 3]
  CHECK(drawableExtent(box) == 3.0);
  TriangleMesh notFinite = box;
  notFinite.vertices[5].y() = std::nan("");
  CHECK(std::isinf(drawableExtent(notFinite)));
  TriangleMesh badIndex = box;
  badIndex.triangles[2][0] = static_cast<VertexIndex>(box.vertexCount());
  CHECK(std::isinf(drawableExtent(badIndex)));
  TriangleMesh noTriangles = box;
  noTriangles.triangles.clear();
  CHECK(std::isinf(drawableExtent(noTriangles)));
}
