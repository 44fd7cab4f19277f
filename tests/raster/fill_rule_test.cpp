// The fill rule on hand-made ties: pixel centres exactly on horizontal, vertical and diagonal
// edges and on a vertex shared by a fan. Every such pixel must be drawn exactly once.

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "raster_test_support.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"

using namespace recode::raster;
using recode::test::drawTriangle;
using recode::test::setCountingState;

namespace {

int countOf(const CpuDevice& dev, int x, int y) {
  return dev.stencilBuffer()[static_cast<std::size_t>(y * dev.width() + x)];
}

}  // namespace

TEST_CASE("square with edges through pixel centres: left and bottom inclusive", "[fill]") {
  // Square [2.5, 6.5]^2 split along its diagonal; centres at x, y in {2.5, ..., 6.5}.
  for (const bool ccw : {true, false}) {
    CpuDevice dev(10, 10);
    setCountingState(dev);
    const WindowVertex p00{2.5f, 2.5f}, p10{6.5f, 2.5f}, p11{6.5f, 6.5f}, p01{2.5f, 6.5f};
    if (ccw) {
      drawTriangle(dev, p00, p10, p11);
      drawTriangle(dev, p00, p11, p01);
    } else {
      drawTriangle(dev, p00, p11, p10);
      drawTriangle(dev, p00, p01, p11);
    }
    for (int y = 0; y < 10; ++y) {
      for (int x = 0; x < 10; ++x) {
        // Left column (x = 2) and bottom row (y = 2) in; right (x = 6) and top (y = 6) out.
        const int expected = (x >= 2 && x <= 5 && y >= 2 && y <= 5) ? 1 : 0;
        INFO("ccw " << ccw << " pixel " << x << "," << y);
        CHECK(countOf(dev, x, y) == expected);
      }
    }
  }
}

TEST_CASE("the other diagonal and shared vertical/horizontal edges are drawn once", "[fill]") {
  CpuDevice dev(12, 12);
  setCountingState(dev);
  // Four triangles meeting at the centre (5.5, 5.5) of pixel (5, 5), with shared edges that
  // run horizontally, vertically and diagonally through pixel centres.
  const WindowVertex c{5.5f, 5.5f};
  const WindowVertex e{9.5f, 5.5f}, n{5.5f, 9.5f}, w{1.5f, 5.5f}, s{5.5f, 1.5f};
  drawTriangle(dev, c, e, n);
  drawTriangle(dev, c, n, w);
  drawTriangle(dev, c, w, s);
  drawTriangle(dev, c, s, e);
  int total = 0;
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 12; ++x) {
      const int v = countOf(dev, x, y);
      INFO("pixel " << x << "," << y);
      REQUIRE(v <= 1);
      total += v;
      // Inside the diamond |dx| + |dy| < 4 (centre distances in pixels) every pixel once.
      const int d = std::abs(x - 5) + std::abs(y - 5);
      if (d < 4)
        CHECK(v == 1);
      if (d > 4)
        CHECK(v == 0);
    }
  }
  // The shared vertex pixel and the pixels on the four shared edges each counted once.
  CHECK(countOf(dev, 5, 5) == 1);
  for (int k = 1; k <= 3; ++k) {
    CHECK(countOf(dev, 5 + k, 5) == 1);
    CHECK(countOf(dev, 5 - k, 5) == 1);
    CHECK(countOf(dev, 5, 5 + k) == 1);
    CHECK(countOf(dev, 5, 5 - k) == 1);
  }
  // On the boundary |dx| + |dy| = 4 exactly the left/bottom-facing outer edges draw: the
  // diamond's lower-left edge (w-s) and upper-left edge (n-w) are left edges; the right ones
  // are not. Pixels (x, y) with x < 5 on the boundary are in, x > 5 are out; the corners:
  // w (1,5) is on two left edges -> in; e (9,5) out; n (5,9) is top-of-left-and-right -> out
  // (the edge e-n is a right edge); s (5,1) lies on w-s (left) and s-e (right) -> out.
  CHECK(countOf(dev, 1, 5) == 1);
  CHECK(countOf(dev, 9, 5) == 0);
  CHECK(countOf(dev, 5, 9) == 0);
  CHECK(countOf(dev, 5, 1) == 0);
  CHECK(countOf(dev, 3, 3) == 1);  // on w-s
  CHECK(countOf(dev, 3, 7) == 1);  // on n-w
  CHECK(countOf(dev, 7, 3) == 0);  // on s-e
  CHECK(countOf(dev, 7, 7) == 0);  // on e-n
  // 25 interior pixels (d < 4) + the 3 left boundary pixels per left edge + the w corner.
  CHECK(total == 25 + 3 + 3 + 1);
}

TEST_CASE("a fan around a vertex at a pixel centre draws that pixel exactly once", "[fill]") {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int fan = 4 + trial % 9;  // gaps stay below 180 degrees
    CpuDevice dev(32, 32);
    setCountingState(dev);
    const WindowVertex centre{16.5f, 16.5f};
    // Random angles, sorted, so the fan covers the full turn; rim on the 1/256 grid.
    std::vector<double> angles;
    for (int k = 0; k < fan; ++k)
      angles.push_back((k + 0.8 * jitter(rng)) * 2.0 * M_PI / fan);
    std::vector<WindowVertex> rim;
    for (double a : angles) {
      const double r = 8.0 + 6.0 * jitter(rng);
      rim.push_back(
          {snapToSubpixel(16.5 + r * std::cos(a)), snapToSubpixel(16.5 + r * std::sin(a))});
    }
    for (int k = 0; k < fan; ++k) {
      const WindowVertex& a = rim[static_cast<std::size_t>(k)];
      const WindowVertex& b = rim[static_cast<std::size_t>((k + 1) % fan)];
      if (trial % 2 == 0) {
        drawTriangle(dev, centre, a, b);
      } else {
        drawTriangle(dev, b, a, centre);  // clockwise: back-facing, same coverage rule
      }
    }
    INFO("trial " << trial);
    CHECK(countOf(dev, 16, 16) == 1);
    for (std::uint8_t v : dev.stencilBuffer())
      REQUIRE(v <= 1);
    // The pixels right next to the centre are inside the fan (the rim is >= 8 px away).
    CHECK(countOf(dev, 15, 16) == 1);
    CHECK(countOf(dev, 17, 16) == 1);
    CHECK(countOf(dev, 16, 15) == 1);
    CHECK(countOf(dev, 16, 17) == 1);
  }
}

TEST_CASE("random meshes of a grid of shared vertices cover every pixel once", "[fill]") {
  // A 4x4-pixel-cell grid whose vertices sit on pixel centres or on random 1/256 offsets,
  // triangulated with random diagonals: a partition of the grid rectangle.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    CpuDevice dev(40, 40);
    setCountingState(dev);
    const int n = 8;  // 8x8 cells of 4 pixels
    std::vector<WindowVertex> v;
    std::uniform_int_distribution<int> off(-200, 200);
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const bool border = i == 0 || j == 0 || i == n || j == n;
        const float jx = border || trial % 3 == 0 ? 0.0f : static_cast<float>(off(rng)) / 256.0f;
        const float jy = border || trial % 3 == 0 ? 0.0f : static_cast<float>(off(rng)) / 256.0f;
        v.push_back(
            {4.5f + 4.0f * static_cast<float>(i) + jx, 4.5f + 4.0f * static_cast<float>(j) + jy});
      }
    }
    std::vector<std::uint32_t> idx;
    std::bernoulli_distribution flip(0.5);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const auto at = [&](int a, int b) { return static_cast<std::uint32_t>(b * (n + 1) + a); };
        const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        if (flip(rng)) {
          idx.insert(idx.end(), {a, b, c, a, c, d});
        } else {
          idx.insert(idx.end(), {a, b, d, b, c, d});
        }
      }
    }
    dev.drawTriangles(v, idx);
    INFO("trial " << trial);
    // Outer square [4.5, 36.5]^2: pixels 4..35 in both axes, each exactly once.
    for (int y = 0; y < 40; ++y) {
      for (int x = 0; x < 40; ++x) {
        const int expected = (x >= 4 && x <= 35 && y >= 4 && y <= 35) ? 1 : 0;
        if (countOf(dev, x, y) != expected) {
          FAIL("pixel " << x << "," << y << " count " << countOf(dev, x, y));
        }
      }
    }
  }
}
