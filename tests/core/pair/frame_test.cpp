// resolveFrame: the scene's view and the command-line overrides turned into a frame.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

#include "recode/pair/frame.hpp"

using namespace recode::core;

namespace {

Aabb bounds(double x0, double y0, double z0, double x1, double y1, double z1) {
  Aabb b;
  b.extend({x0, y0, z0});
  b.extend({x1, y1, z1});
  return b;
}

double pixelW(const FrameSpec& f) {
  return (f.window.umax - f.window.umin) / f.width;
}
double pixelH(const FrameSpec& f) {
  return (f.window.vmax - f.window.vmin) / f.height;
}

}  // namespace

TEST_CASE("defaults: 800x800, the bounds with a 5% margin, square pixels") {
  // Along z the image plane is (x, y): 4 wide, 2 high.
  const FrameSpec f = resolveFrame(ViewSpec{}, bounds(0, 0, 0, 4, 2, 1));
  CHECK(f.width == 800);
  CHECK(f.height == 800);
  // Margin 0.2 on every side (5% of the larger extent, 4), then the height widened to match.
  CHECK(f.window.umin == Approx(-0.2));
  CHECK(f.window.umax == Approx(4.2));
  CHECK(pixelW(f) == Approx(pixelH(f)));
  CHECK(0.5 * (f.window.vmin + f.window.vmax) == Approx(1.0));
}

TEST_CASE("a default window for a resolution is centred on the bounds, pixel for pixel") {
  // Bounds [-2, 2] x [-1, 1] on the plane: margin 0.2 (5% of 4) gives [-2.2, 2.2] x [-1.2, 1.2],
  // centred on 0 exactly. At 40 x 20 the pixel is max(4.4 / 40, 2.4 / 20) = 0.12 (the height
  // decides), and each side is the centre -+ half the pixel times the pixel count.
  const ViewWindow w =
      defaultWindow(ViewAxis::Z, bounds(-2, -1, 0, 2, 1, 1), std::array<int, 2>{40, 20});
  const double margin = kDefaultWindowMargin * 4;
  const double du = (2 + margin) - (-2 - margin), dv = (1 + margin) - (-1 - margin);
  const double perPixel = std::max(du / 40, dv / 20);
  CHECK(perPixel == Approx(0.12));
  CHECK(w.umin == 0.0 - 0.5 * perPixel * 40);
  CHECK(w.umax == 0.0 + 0.5 * perPixel * 40);
  CHECK(w.vmin == 0.0 - 0.5 * perPixel * 20);
  CHECK(w.vmax == 0.0 + 0.5 * perPixel * 20);
  CHECK(w.umax == -w.umin);
}

TEST_CASE("the image plane follows the axis") {
  ViewSpec spec;
  spec.axis = ViewAxis::X;  // plane (y, z)
  const FrameSpec f = resolveFrame(spec, bounds(0, 10, 20, 1, 11, 22));
  CHECK(f.axis == ViewAxis::X);
  CHECK(0.5 * (f.window.umin + f.window.umax) == Approx(10.5));
  CHECK(0.5 * (f.window.vmin + f.window.vmax) == Approx(21.0));
}

TEST_CASE("a scene window and resolution are used as given") {
  ViewSpec spec;
  spec.window = ViewWindow{-1, -2, 3, 4};
  spec.resolution = std::array<int, 2>{30, 20};
  const FrameSpec f = resolveFrame(spec, bounds(0, 0, 0, 1, 1, 1));
  CHECK(f.width == 30);
  CHECK(f.height == 20);
  CHECK(f.window.umin == -1);
  CHECK(f.window.vmax == 4);
}

TEST_CASE("a width alone keeps pixels square; width and height are taken as is") {
  ViewSpec spec;
  spec.window = ViewWindow{0, 0, 4, 1};
  FrameOverrides o;
  o.width = 64;
  const FrameSpec f = resolveFrame(spec, {}, o);
  CHECK(f.width == 64);
  CHECK(f.height == 16);
  o.height = 10;
  const FrameSpec g = resolveFrame(spec, {}, o);
  CHECK(g.height == 10);
}

TEST_CASE("pixel size: square pixels of that size cover the window") {
  ViewSpec spec;
  spec.window = ViewWindow{0, 0, 1.05, 0.5};
  spec.pixelSize = 0.1;
  const FrameSpec f = resolveFrame(spec, {});
  CHECK(f.width == 11);
  CHECK(f.height == 5);
  CHECK(pixelW(f) == Approx(0.1));
  CHECK(pixelH(f) == Approx(0.1));
  CHECK(0.5 * (f.window.umin + f.window.umax) == Approx(0.525));
  // An override of the resolution replaces the scene's pixel size.
  FrameOverrides o;
  o.width = 20;
  o.height = 20;
  CHECK(resolveFrame(spec, {}, o).width == 20);
}

TEST_CASE("frame errors") {
  ViewSpec spec;
  spec.window = ViewWindow{0, 0, 1, 1};
  FrameOverrides both;
  both.width = 10;
  both.pixelSize = 0.1;
  CHECK_THROWS_WITH(resolveFrame(spec, {}, both),
                    Catch::Contains("a resolution or a pixel size, not both"));
  FrameOverrides tooMany;
  tooMany.pixelSize = 1e-6;
  CHECK_THROWS_WITH(resolveFrame(spec, {}, tooMany), Catch::Contains("at most 16384 per side"));
  FrameOverrides zero;
  zero.width = 0;
  CHECK_THROWS_WITH(resolveFrame(spec, {}, zero), Catch::Contains("width 0 is outside 1..16384"));
  CHECK_THROWS_WITH(resolveFrame(ViewSpec{}, Aabb{}),
                    Catch::Contains("cannot choose a view window for an empty scene"));
}
