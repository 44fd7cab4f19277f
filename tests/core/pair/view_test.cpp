// The world-to-window view (docs/algorithm.md section 2): image planes per axis, depth direction,
// pre-snapping, the inverse mapping, facing preserved, and the errors.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "recode/geometry/generators.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"

using namespace recode;
using core::OrthoView;
using core::ViewAxis;

TEST_CASE("image planes and depth direction per axis", "[view]") {
  const core::ViewWindow win{-2.0, -1.0, 2.0, 1.0};
  const Eigen::Vector3d p(0.5, -0.25, 0.75);
  // axis z: (u, v) = (x, y); axis x: (y, z); axis y: (z, x).
  const OrthoView vz(ViewAxis::Z, win, 400, 200, -1.0, 1.0);
  const OrthoView vx(ViewAxis::X, win, 400, 200, -1.0, 1.0);
  const OrthoView vy(ViewAxis::Y, win, 400, 200, -1.0, 1.0);
  CHECK(vz.toPlane(p) == Eigen::Vector3d(0.5, -0.25, 0.75));
  CHECK(vx.toPlane(p) == Eigen::Vector3d(-0.25, 0.75, 0.5));
  CHECK(vy.toPlane(p) == Eigen::Vector3d(0.75, 0.5, -0.25));
  for (const OrthoView* v : {&vz, &vx, &vy})
    CHECK(v->fromPlane(v->toPlane(p)) == p);

  // Window: u = 0.5 -> x = (0.5 + 2) / 4 * 400 = 250; v = -0.25 -> y = 0.75 / 2 * 200 = 75.
  const raster::WindowVertex w = vz.toWindow(p);
  CHECK(w.x == 250.0f);
  CHECK(w.y == 75.0f);
  // Depth grows as the coordinate along the axis decreases: z = 0.75 -> (1 - 0.75) / 2.
  CHECK(w.z == 0.125f);
  CHECK(vz.toWindow(Eigen::Vector3d(0, 0, 1.0)).z == 0.0f);
  CHECK(vz.toWindow(Eigen::Vector3d(0, 0, -1.0)).z == 1.0f);
}

TEST_CASE("window x and y are pre-snapped and unproject back within 1/256 pixel", "[view]") {
  const OrthoView v(ViewAxis::Z, {0.0, 0.0, 3.0, 7.0}, 311, 977, -5.0, 5.0);
  for (double t = 0.0; t < 1.0; t += 0.0137) {
    const Eigen::Vector3d p(3.0 * t, 7.0 * (1.0 - t), 10.0 * t - 5.0);
    const raster::WindowVertex w = v.toWindow(p);
    CHECK(raster::snapToSubpixel(w.x) == w.x);
    CHECK(raster::snapToSubpixel(w.y) == w.y);
    const Eigen::Vector3d back = v.toWorld(w.x, w.y, w.z);
    CHECK(std::fabs(back.x() - p.x()) <= 0.5 / 256.0 * v.pixelWidth() + 1e-12);
    CHECK(std::fabs(back.y() - p.y()) <= 0.5 / 256.0 * v.pixelHeight() + 1e-12);
    CHECK(std::fabs(back.z() - p.z()) <= 1e-6);
  }
}

TEST_CASE("outward faces toward the viewer are front-facing for every axis", "[view]") {
  const core::TriangleMesh box = core::makeBox(0.5, 0.4, 0.3);
  for (const ViewAxis axis : {ViewAxis::X, ViewAxis::Y, ViewAxis::Z}) {
    const OrthoView view(axis, {-1.0, -1.0, 1.0, 1.0}, 64, 64, -1.0, 1.0);
    const auto wv = view.toWindow(box);
    for (const auto& t : box.triangles) {
      const Eigen::Vector3d n =
          (box.vertices[t[1]] - box.vertices[t[0]]).cross(box.vertices[t[2]] - box.vertices[t[0]]);
      const double towardViewer = view.toPlane(n).z();  // + side of the axis is the viewer
      const raster::WindowVertex &a = wv[t[0]], &b = wv[t[1]], &c = wv[t[2]];
      const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      if (towardViewer > 0)
        CHECK(area > 0);  // counter-clockwise: front
      if (towardViewer < 0)
        CHECK(area < 0);
      if (towardViewer == 0)
        CHECK(area == 0);
    }
  }
}

TEST_CASE("bad views are rejected with a clear message", "[view]") {
  const core::ViewWindow win{-1.0, -1.0, 1.0, 1.0};
  CHECK_THROWS_WITH(OrthoView(ViewAxis::Z, win, 0, 10, 0.0, 1.0),
                    Catch::Contains("resolution 0x10 is outside 1..16384"));
  CHECK_THROWS_WITH(OrthoView(ViewAxis::Z, win, 10, 20000, 0.0, 1.0), Catch::Contains("10x20000"));
  CHECK_THROWS_WITH(OrthoView(ViewAxis::Z, {1.0, -1.0, 1.0, 1.0}, 10, 10, 0.0, 1.0),
                    Catch::Contains("umin < umax"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(OrthoView(ViewAxis::Z, {nan, -1.0, 1.0, 1.0}, 10, 10, 0.0, 1.0),
                    Catch::Contains("must be finite"));
  CHECK_THROWS_WITH(OrthoView(ViewAxis::Z, win, 10, 10, 1.0, 1.0), Catch::Contains("depth range"));
  const OrthoView v(ViewAxis::Z, win, 1000, 1000, -1.0, 1.0);
  // 1000 px per 2 units: x = 100 maps to 50500 px, beyond the 24.8 fixed-point range.
  CHECK_THROWS_WITH(v.toWindow(Eigen::Vector3d(100.0, 0.0, 0.0)),
                    Catch::Contains("beyond the +-32768 pixel range"));
  CHECK_THROWS_WITH(v.toWindow(Eigen::Vector3d(0.0, 0.0, 2.0)),
                    Catch::Contains("outside the view's depth range"));
  CHECK_THROWS_WITH(v.toWindow(Eigen::Vector3d(nan, 0.0, 0.0)), Catch::Contains("beyond"));
}
