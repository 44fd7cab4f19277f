// Watertightness: generated closed meshes drawn at many random poses must give every pixel
// exactly as many front fragments as back fragments, and a convex mesh at most one of each.
// This is the property RECODE's face counting relies on; a double-drawn shared edge or a
// crack would show up here as an unequal count.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>

#include "recode/core/generators.hpp"
#include "recode/core/mesh.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"

using namespace recode;
using raster::CompareFunc;
using raster::CpuDevice;
using raster::CullMode;
using raster::Face;
using raster::StencilOp;

namespace {

// Orthographic view along -z fitted to the frame with a random margin and sub-pixel offset;
// x, y pre-snapped to 1/256 pixel, depth mapped so that larger world z is nearer (smaller).
std::vector<raster::WindowVertex> project(const core::TriangleMesh& mesh, int w, int h,
                                          std::mt19937& rng) {
  const core::Aabb box = core::boundingBox(mesh);
  std::uniform_real_distribution<double> margin(0.05, 0.3), shift(-0.5, 0.5);
  const Eigen::Vector3d size = box.max - box.min;
  const double scale = std::min(w / size.x(), h / size.y()) * (1.0 - margin(rng));
  const double ox = 0.5 * (w - scale * size.x()) + shift(rng);
  const double oy = 0.5 * (h - scale * size.y()) + shift(rng);
  std::vector<raster::WindowVertex> out;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    const double z = (box.max.z() - p.z()) / (size.z() > 0 ? size.z() : 1.0);
    out.push_back({raster::snapToSubpixel(ox + scale * (p.x() - box.min.x())),
                   raster::snapToSubpixel(oy + scale * (p.y() - box.min.y())),
                   static_cast<float>(0.05 + 0.9 * z)});
  }
  return out;
}

std::vector<std::uint32_t> indices(const core::TriangleMesh& mesh) {
  std::vector<std::uint32_t> out;
  for (const auto& t : mesh.triangles)
    out.insert(out.end(), t.begin(), t.end());
  return out;
}

// Counts front and back fragments per pixel in two culled passes.
struct Counts {
  std::vector<std::uint8_t> front, back;
};
Counts countFragments(const std::vector<raster::WindowVertex>& v,
                      const std::vector<std::uint32_t>& idx, int w, int h) {
  CpuDevice dev(w, h);
  dev.setDepthFunc(CompareFunc::Always);
  dev.setDepthWriteMask(false);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr});
  Counts c;
  dev.setCullMode(CullMode::Back);
  dev.drawTriangles(v, idx);
  c.front = dev.readStencil({0, 0, w, h});
  dev.clearStencil(0);
  dev.setCullMode(CullMode::Front);
  dev.drawTriangles(v, idx);
  c.back = dev.readStencil({0, 0, w, h});
  return c;
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
    const Counts c = countFragments(v, indices(mesh), w, h);
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
    const Counts c = countFragments(project(both, w, h, rng), indices(both), w, h);
    int unequal = 0;
    for (std::size_t i = 0; i < c.front.size(); ++i) {
      unequal += c.front[i] != c.back[i];
      REQUIRE(c.front[i] <= 2);
    }
    INFO("trial " << trial);
    CHECK(unequal == 0);
  }
}
