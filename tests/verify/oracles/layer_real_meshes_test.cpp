// The layered pair on real closed meshes (CGAL's demo meshes, from the installed libcgal-demo
// package at test time) against CGAL: every MOR pixel against exact crossings, every pose's
// verdict against do_intersect with the bounded-sides test, and the containments that a test of
// surfaces alone (FCL's mesh-mesh test) reports as apart.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>

#include "recode/geometry/closed_mesh.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/layer_oracle.hpp"

#include "closed_mesh_support.hpp"

using namespace recode;
using Eigen::Vector3d;

using recode::test::frameAround;

namespace {

// The mesh moved and scaled so that its box's longer side is 2, centred at the origin.
core::TriangleMesh normalised(core::TriangleMesh m) {
  const core::Aabb box = core::boundingBox(m);
  const double scale = 2.0 / box.extent().maxCoeff();
  for (Vector3d& v : m.vertices)
    v = (v - box.center()) * scale;
  return m;
}

}  // namespace

TEST_CASE("real closed meshes: the layered pair against CGAL, pixel by pixel and pose by pose",
          "[layered][real]") {
  const std::filesystem::path dir(RECODE_CGAL_DEMO_MESHES);
  if (!std::filesystem::exists(dir / "elephant.off"))
    FAIL("CGAL's demo meshes are not at " << dir.string()
                                          << " (install libcgal-demo: scripts/setup.sh)");
  std::mt19937 rng(6820);
  std::uniform_real_distribution<double> inBox(-0.9, 0.9), radius(0.05, 0.35);
  long long pixels = 0, ties = 0, contained = 0, missedBySurfaces = 0, colliding = 0, apart = 0;
  for (const char* name : {"elephant.off", "knot1.off", "eight.off"}) {
    const core::TriangleMesh mesh = normalised(core::readMesh(dir / name));
    REQUIRE_NOTHROW(core::validateClosedMesh(mesh, name));
    for (int n = 0; n < 12; ++n) {
      const core::TriangleMesh ball = core::transformed(
          core::makeSphere(radius(rng), 16, 8),
          Eigen::Isometry3d(Eigen::Translation3d(inBox(rng), inBox(rng), inBox(rng))));
      const auto axis = static_cast<core::ViewAxis>(n % 3);
      const core::FrameSpec frame = frameAround(axis, mesh, ball, n % 2 == 0 ? 128 : 256);
      raster::CpuDevice device(frame.width, frame.height);
      core::PairRequest request;
      request.frame = frame;
      const core::LayeredPairResult r = core::collideLayered(device, mesh, ball, request);
      INFO(name << " pose " << n);
      const verify::LayerPixelJudgement j = verify::judgeLayeredPixels(mesh, ball, frame, r);
      CHECK(j.disagreed == 0);
      pixels += j.pixels;
      ties += j.ties;
      const bool exact = verify::closedMeshesMeet(mesh, ball);
      if (j.exactInterfering > 0)
        CHECK(r.collide);
      if (r.collide && j.ties == 0)
        CHECK(exact);
      if (r.containment == core::Containment::BInsideA) {
        ++contained;
        CHECK(exact);
        missedBySurfaces += verify::closedSurfacesMeet(mesh, ball) ? 0 : 1;
      }
      colliding += r.collide ? 1 : 0;
      apart += exact ? 0 : 1;
    }
  }
  // Small balls CGAL finds wholly inside each mesh (they meet it, their surfaces do not): the
  // layered pair must say contained, where a test of surfaces alone says apart.
  for (const char* name : {"elephant.off", "knot1.off", "eight.off"}) {
    const core::TriangleMesh mesh = normalised(core::readMesh(dir / name));
    int found = 0;
    for (int n = 0; n < 60 && found < 2; ++n) {
      const core::TriangleMesh ball = core::transformed(
          core::makeSphere(0.04, 12, 6),
          Eigen::Isometry3d(Eigen::Translation3d(inBox(rng), inBox(rng), inBox(rng))));
      if (!verify::closedMeshesMeet(mesh, ball) || verify::closedSurfacesMeet(mesh, ball))
        continue;
      ++found;
      const auto axis = static_cast<core::ViewAxis>(n % 3);
      const core::FrameSpec frame = frameAround(axis, mesh, ball, 256);
      raster::CpuDevice device(frame.width, frame.height);
      core::PairRequest request;
      request.frame = frame;
      const core::LayeredPairResult r = core::collideLayered(device, mesh, ball, request);
      INFO(name << " inside, pose " << n);
      CHECK(r.collide);
      CHECK(r.containment == core::Containment::BInsideA);
      CHECK(verify::judgeLayeredPixels(mesh, ball, frame, r).disagreed == 0);
      contained += r.containment == core::Containment::BInsideA ? 1 : 0;
      ++missedBySurfaces;
    }
    CHECK(found >= 1);  // a knot's tube is thin: one in 60 random centres may be all
  }
  WARN("real meshes: " << pixels << " MOR pixels, " << ties << " ties; " << colliding
                       << " poses colliding, " << apart << " apart; " << contained
                       << " balls inside a mesh, " << missedBySurfaces
                       << " of them apart for a test of surfaces alone");
  CHECK(contained >= 4);
  CHECK(missedBySurfaces >= 4);
  CHECK(ties * 1000 <= pixels);
}
