// Watertightness: generated closed meshes drawn at many random poses must give every pixel
// exactly as many front fragments as back fragments, and a convex mesh at most one of each.
// This is the property RECODE's face counting relies on; a double-drawn shared edge or a
// crack would show up here as an unequal count.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/facing_counts.hpp"

using namespace recode;
using raster::CpuDevice;

namespace {

// A view along z that fits the mesh into the frame with a random margin and a random
// sub-pixel offset, so that edges and vertices land at every sub-pixel phase.
std::vector<raster::WindowVertex> project(const core::TriangleMesh& mesh, int w, int h,
                                          std::mt19937& rng) {
  const core::Aabb box = core::boundingBox(mesh);
  std::uniform_real_distribution<double> margin(0.05, 0.3), shift(-0.5, 0.5);
  const Eigen::Vector3d size = box.extent();
  // World units per pixel, the same along both window axes.
  const double pixel = std::max(size.x() / w, size.y() / h) / (1.0 - margin(rng));
  const double u0 = box.center().x() - 0.5 * w * pixel + shift(rng) * pixel;
  const double v0 = box.center().y() - 0.5 * h * pixel + shift(rng) * pixel;
  const double pad = 0.05 * size.z() + 1e-9;
  const core::OrthoView view(core::ViewAxis::Z, {u0, v0, u0 + w * pixel, v0 + h * pixel}, w, h,
                             box.min.z() - pad, box.max.z() + pad);
  return view.toWindow(mesh);
}

raster::FacingCounts countFragments(const std::vector<raster::WindowVertex>& v,
                                    const core::TriangleMesh& mesh, int w, int h) {
  CpuDevice dev(w, h);
  return raster::countFacingFragments(dev, v, core::triangleIndices(mesh));
}

core::TriangleMesh randomShape(std::mt19937& rng, int k) {
  std::uniform_int_distribution<int> seg(3, 40), rings(2, 16);
  std::uniform_real_distribution<double> len(0.2, 3.0);
  switch (k % 6) {
    case 0:
      return core::makeCone(len(rng), len(rng), seg(rng));
    case 1:
      return core::makeCylinder(len(rng), len(rng), seg(rng));
    case 2: {
      const double r0 = len(rng), r1 = len(rng) * 0.5;
      return core::makeCappedCone(r0, r1, std::abs(r0 - r1) + len(rng), seg(rng), rings(rng));
    }
    case 3:
      return core::makeEllipsoid(len(rng), len(rng), len(rng), seg(rng), rings(rng));
    case 4:
      return core::makeSphere(len(rng), seg(rng), rings(rng));
    default:
      return core::makeBox(len(rng), len(rng), len(rng));
  }
}

Eigen::Quaterniond randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

}  // namespace

TEST_CASE("convex meshes at random poses: one front and one back fragment inside", "[watertight]") {
  std::mt19937 rng(424242);
  const int sizes[][2] = {{37, 53}, {128, 128}, {300, 200}};
  long long coveredPixels = 0;
  for (int trial = 0; trial < 180; ++trial) {
    const int w = sizes[trial % 3][0], h = sizes[trial % 3][1];
    const core::TriangleMesh shape = randomShape(rng, trial);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = randomRotation(rng).toRotationMatrix();
    const core::TriangleMesh mesh = core::transformed(shape, pose);
    const auto v = project(mesh, w, h, rng);
    const raster::FacingCounts c = countFragments(v, mesh, w, h);
    int unequal = 0, overTwo = 0, covered = 0;
    for (std::size_t i = 0; i < c.front.size(); ++i) {
      unequal += c.front[i] != c.back[i];
      overTwo += c.front[i] > 1 || c.back[i] > 1;
      covered += c.front[i] == 1;
    }
    INFO("trial " << trial << " (" << w << "x" << h << ", " << mesh.triangles.size()
                  << " triangles)");
    CHECK(unequal == 0);
    CHECK(overTwo == 0);
    CHECK(covered > w * h / 20);  // the fit makes the silhouette a sizeable part of the frame
    coveredPixels += covered;
  }
  CHECK(coveredPixels > 100000);
}

TEST_CASE("two overlapping convex meshes in one draw: front count equals back count",
          "[watertight]") {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 60; ++trial) {
    core::TriangleMesh a = randomShape(rng, trial);
    core::TriangleMesh b = randomShape(rng, trial + 3);
    Eigen::Isometry3d pa = Eigen::Isometry3d::Identity(), pb = Eigen::Isometry3d::Identity();
    pa.linear() = randomRotation(rng).toRotationMatrix();
    pb.linear() = randomRotation(rng).toRotationMatrix();
    pb.translation() = Eigen::Vector3d(0.7, -0.4, 0.3);
    a = core::transformed(a, pa);
    b = core::transformed(b, pb);
    // Concatenate into one closed (non-convex, self-overlapping) mesh.
    core::TriangleMesh both = a;
    const auto offset = static_cast<std::uint32_t>(a.vertices.size());
    both.vertices.insert(both.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (auto t : b.triangles)
      both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const int w = 160, h = 120;
    const raster::FacingCounts c = countFragments(project(both, w, h, rng), both, w, h);
    int unequal = 0;
    for (std::size_t i = 0; i < c.front.size(); ++i) {
      unequal += c.front[i] != c.back[i];
      REQUIRE(c.front[i] <= 2);
    }
    INFO("trial " << trial);
    CHECK(unequal == 0);
  }
}
