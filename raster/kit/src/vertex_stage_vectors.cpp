// The vertex-stage vectors (vertex_stage_vectors.hpp). Two kinds:
//
// - Rotated and far blocks: a random rotation and translation, a window around the block with
//   ranges and a frame size that are not powers of two, a few random vertices, and vertices
//   *aimed* at one wrong reading each: a start point is moved along one coordinate until its
//   window x or y lies next to a snap tie, or its z next to the midpoint of two floats, then
//   stepped until the reading's bits differ from the contract's. Orders of the sums, fusion and
//   the quotient's association change a value by an ulp or so, which shows only there.
// - The special cases, built so that the stage's arithmetic is exact: x or y whose x 256 is
//   exactly k + 0.5 (and a hair off it), world coordinates -0 and small negatives with
//   umin = 0, z exactly halfway between two floats, and z below the smallest normal float.
//
// Random numbers come from detail::Rng (std::mt19937_64's raw bits, so the same everywhere);
// every double is made from them with IEEE operations in a fixed order.

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "family.hpp"
#include "recode/kit/vertex_stage_vectors.hpp"

namespace recode::kit {

namespace {

using detail::Rng;
using raster::Pose;
using raster::VertexTransform;
using raster::WindowMapping;
using raster::WindowPosition;
using R = VertexStageReading;
using Vec3 = std::array<double, 3>;

// The views: the world axes that become (u, v, d).
struct View {
  const char* name;
  std::array<int, 3> axes;
};
constexpr std::array<View, 3> kViews = {{{"z", {0, 1, 2}}, {"x", {1, 2, 0}}, {"y", {2, 0, 1}}}};

// A double in [0, 1) from 53 raw bits, and in [lo, hi).
double unit(Rng& rng) {
  return static_cast<double>(rng.uniform(0, (1LL << 53) - 1)) * 0x1p-53;
}
double between(Rng& rng, double lo, double hi) {
  return lo + (hi - lo) * unit(rng);
}

// A rotation from a random unit quaternion (a, b, c, d), drawn in the unit ball and normalised.
std::array<double, 9> randomRotation(Rng& rng) {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0, n2 = 0.0;
  do {
    a = between(rng, -1.0, 1.0);
    b = between(rng, -1.0, 1.0);
    c = between(rng, -1.0, 1.0);
    d = between(rng, -1.0, 1.0);
    n2 = ((a * a + b * b) + c * c) + d * d;
  } while (n2 > 1.0 || n2 < 0.0625);
  const double n = std::sqrt(n2);
  a /= n;
  b /= n;
  c /= n;
  d /= n;
  return {1.0 - 2.0 * (c * c + d * d), 2.0 * (b * c - a * d),       2.0 * (b * d + a * c),
          2.0 * (b * c + a * d),       1.0 - 2.0 * (b * b + d * d), 2.0 * (c * d - a * b),
          2.0 * (b * d - a * c),       2.0 * (c * d + a * b),       1.0 - 2.0 * (b * b + c * c)};
}

// A frame size between 300 and 3000 pixels that is not a power of two.
double frameSize(Rng& rng) {
  long long n = rng.uniform(300, 3000);
  if ((n & (n - 1)) == 0)
    ++n;
  return static_cast<double>(n);
}

// A window around the world box of the block [-half, half]^3 under `pose`, with a random margin
// on each side; each range is one subtraction, as a view makes it.
WindowMapping windowAround(Rng& rng, const std::array<int, 3>& axes, const Pose& pose,
                           double half) {
  Vec3 lo{DBL_MAX, DBL_MAX, DBL_MAX};
  Vec3 hi{-DBL_MAX, -DBL_MAX, -DBL_MAX};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{(corner & 1) ? half : -half, (corner & 2) ? half : -half,
                 (corner & 4) ? half : -half};
    const Vec3 w = raster::poseVertex(pose, p);
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], w[i]);
      hi[i] = std::max(hi[i], w[i]);
    }
  }
  const auto below = [&](std::size_t i) {
    return lo[i] - (hi[i] - lo[i]) * between(rng, 0.02, 0.2);
  };
  const auto above = [&](std::size_t i) {
    return hi[i] + (hi[i] - lo[i]) * between(rng, 0.02, 0.2);
  };
  const auto u = static_cast<std::size_t>(axes[0]);
  const auto v = static_cast<std::size_t>(axes[1]);
  const auto d = static_cast<std::size_t>(axes[2]);
  WindowMapping m;
  m.axes = axes;
  m.umin = below(u);
  m.urange = above(u) - m.umin;
  m.width = frameSize(rng);
  m.vmin = below(v);
  m.vrange = above(v) - m.vmin;
  m.height = frameSize(rng);
  m.depthMax = above(d);
  m.depthRange = m.depthMax - below(d);
  return m;
}

WindowPosition position(const VertexTransform& t, const Vec3& p) {
  return raster::mapToWindow(t.window, raster::poseVertex(t.pose, p));
}

double coordinate(const WindowPosition& w, int c) {
  return c == 0 ? w.x : (c == 1 ? w.y : w.z);
}

double ulp(double x) {
  const double a = std::fabs(x);
  return std::nextafter(a, DBL_MAX) - a;
}

bool caught(R reading, const VertexTransform& t, const Vec3& p) {
  return !sameBits(vertexStageAs(reading, t, p), raster::vertexStage(t, p));
}

// Rounding boundaries near s, the nearest first: for x and y (c < 2) the snap ties
// (k + 0.5) / 256, for z the midpoints of two neighbouring floats.
std::vector<double> boundariesNear(double s, int c) {
  std::vector<double> out;
  std::vector<int> offsets = {0};
  for (int i = 1; i <= 7; ++i) {
    offsets.push_back(-i);
    offsets.push_back(i);
  }
  if (c < 2) {
    const double k = std::floor(s * raster::kSubpixelOne);
    for (const int i : offsets)
      out.push_back((k + 0.5 + static_cast<double>(i)) / raster::kSubpixelOne);
    return out;
  }
  float f = static_cast<float>(s);
  if (static_cast<double>(f) > s)
    f = std::nextafter(f, -FLT_MAX);  // f <= s < the next float
  for (const int i : offsets) {
    float g = f;
    for (int k = 0; k < std::abs(i); ++k)
      g = std::nextafter(g, i < 0 ? -FLT_MAX : FLT_MAX);
    const float next = std::nextafter(g, FLT_MAX);
    out.push_back((static_cast<double>(g) + static_cast<double>(next)) / 2.0);
  }
  return out;
}

// Moves p along the local coordinate that moves window coordinate c fastest until c lies at
// `boundary` (Newton: the stage is affine before its roundings), then steps it, either way,
// until `reading` gets the vertex wrong; nullopt after 256 steps each way.
std::optional<Vec3> aimAt(const VertexTransform& t, Vec3 p, int c, double boundary, R reading) {
  const WindowMapping& m = t.window;
  const auto row = static_cast<std::size_t>(m.axes[static_cast<std::size_t>(c)]);
  const double scale =
      c == 0 ? m.width / m.urange : (c == 1 ? m.height / m.vrange : -1.0 / m.depthRange);
  std::size_t j = 0;
  for (std::size_t k = 1; k < 3; ++k) {
    if (std::fabs(t.pose.linear[3 * row + k]) > std::fabs(t.pose.linear[3 * row + j]))
      j = k;
  }
  const double slope = t.pose.linear[3 * row + j] * scale;
  if (slope == 0.0)
    return std::nullopt;
  for (int i = 0; i < 4; ++i) {
    const double s = coordinate(position(t, p), c);
    if (s == boundary)
      break;
    p[j] += (boundary - s) / slope;
  }
  // A step moves the coordinate by about an ulp of it or of the world coordinate it comes from,
  // whichever is coarser.
  const double world = raster::poseVertex(t.pose, p)[row];
  const double step = std::max({ulp(coordinate(position(t, p), c)) / std::fabs(slope),
                                ulp(world) / std::fabs(t.pose.linear[3 * row + j]), ulp(p[j])});
  const double start = p[j];
  constexpr int kSteps = 256;
  for (int k = 0; k <= kSteps; ++k) {
    for (const double sign : {1.0, -1.0}) {
      if (k == 0 && sign < 0.0)
        continue;
      Vec3 q = p;
      q[j] = start + sign * static_cast<double>(k) * step;
      if (raster::drawablePosition(position(t, q)) && caught(reading, t, q))
        return q;
    }
  }
  return std::nullopt;
}

// A random point of the block [-half, half]^3, kept off its faces.
Vec3 randomLocal(Rng& rng, double half) {
  return {between(rng, -0.8 * half, 0.8 * half), between(rng, -0.8 * half, 0.8 * half),
          between(rng, -0.8 * half, 0.8 * half)};
}

// The window coordinate (0 = x, 1 = y, 2 = z) that world axis `world` becomes.
int windowCoordinateOf(const std::array<int, 3>& axes, int world) {
  for (int c = 0; c < 3; ++c) {
    if (axes[static_cast<std::size_t>(c)] == world)
      return c;
  }
  throw std::logic_error("vertex-stage vectors: axes are not a permutation");
}

// A vertex that `reading` gets wrong, aimed first at window coordinate `c`, then at the others,
// from up to 32 random start points.
Vec3 aimedVertex(Rng& rng, const VertexTransform& t, double half, R reading, int c) {
  for (int attempt = 0; attempt < 32; ++attempt) {
    const Vec3 start = randomLocal(rng, half);
    for (const int offset : {0, 1, 2}) {
      const int coord = (c + offset) % 3;
      for (const double boundary : boundariesNear(coordinate(position(t, start), coord), coord)) {
        if (const std::optional<Vec3> p = aimAt(t, start, coord, boundary, reading))
          return *p;
      }
    }
  }
  throw std::logic_error("vertex-stage vectors: no vertex found that " +
                         std::string(vertexStageReadingName(reading)) + " gets wrong");
}

struct Aim {
  R reading;
  int world;  // the world axis (0 = x, 1 = y, 2 = z) to aim through; -1: window z
};

// A rotated, translated block seen along `view`: `randomCount` random vertices, then one aimed
// vertex per entry of `aims`.
VertexStageVector rotatedBlock(std::string name, std::uint64_t seed, const View& view,
                               double translationMin, double translationMax, int randomCount,
                               const std::vector<Aim>& aims) {
  Rng rng(seed);
  VertexStageVector v;
  v.name = std::move(name);
  const double half = between(rng, 0.5, 4.0);
  v.transform.pose.linear = randomRotation(rng);
  for (double& t : v.transform.pose.translation) {
    const double magnitude = between(rng, translationMin, translationMax);
    t = rng.chance(50) ? magnitude : -magnitude;
  }
  v.transform.window = windowAround(rng, view.axes, v.transform.pose, half);
  for (int i = 0; i < randomCount; ++i)
    v.local.push_back(randomLocal(rng, half));
  for (const Aim& aim : aims) {
    const int c = aim.world < 0 ? 2 : windowCoordinateOf(view.axes, aim.world);
    v.local.push_back(aimedVertex(rng, v.transform, half, aim.reading, c));
  }
  return v;
}

// The local point of an identity pose whose world coordinates along the view's (u, v, d) are
// the given ones.
Vec3 localFor(const View& view, double u, double v, double d) {
  Vec3 p{};
  p[static_cast<std::size_t>(view.axes[0])] = u;
  p[static_cast<std::size_t>(view.axes[1])] = v;
  p[static_cast<std::size_t>(view.axes[2])] = d;
  return p;
}

// Identity pose, a window whose arithmetic is exact: x = (u + 4) / 8 * 256, y = (v + 2) / 8 *
// 512, z = (4 - d) / 8. x 256 exactly k + 0.5 for even and odd k of either sign, exactly -0.5
// (which snaps to -0), and a hair (2^-20) off a tie, where x rounded to float first lands on
// the tie; y alike.
VertexStageVector snapTies(const View& view, double k) {
  VertexStageVector v;
  v.name = std::string("snap_ties_") + view.name;
  WindowMapping& m = v.transform.window;
  m = {view.axes, -4.0, 8.0, 256.0, -2.0, 8.0, 512.0, 4.0, 8.0};
  const auto uFor = [](double x256) { return x256 / 8192.0 - 4.0; };  // x 256 = (u + 4) 8192
  const auto vFor = [](double y256) { return y256 / 16384.0 - 2.0; };
  const double onGridU = uFor(2.0 * k);
  const double onGridV = vFor(3.0 * k);
  const double hair = 0x1p-20;
  for (const double x256 :
       {k + 0.5, k + 1.5, -(k + 0.5), -(k + 1.5), -0.5, k + 0.5 + hair, k + 1.5 - hair})
    v.local.push_back(localFor(view, uFor(x256), onGridV, 0.5));
  for (const double y256 : {2.0 * k + 0.5, 2.0 * k + 1.5, -(2.0 * k + 0.5), -(2.0 * k + 1.5), -0.5,
                            2.0 * k + 0.5 + hair, 2.0 * k + 1.5 - hair})
    v.local.push_back(localFor(view, onGridU, vFor(y256), -1.25));
  return v;
}

// Identity pose translated by (-0, -0, -0), umin = vmin = 0 and depthMax = 0: world -0 where the
// block's own coordinate is -0 and every other one negative (0 times a negative is -0), and
// small negatives, all of which snap to -0; one vertex at +0 beside them.
VertexStageVector signedZeros(const View& view) {
  VertexStageVector v;
  v.name = std::string("signed_zero_") + view.name;
  v.transform.pose.translation = {-0.0, -0.0, -0.0};
  v.transform.window = {view.axes, 0.0, 2.0, 300.0, 0.0, 3.0, 200.0, 0.0, 4.0};
  const double tiny = 0x1p-20;  // |x| = 2^-20 / 2 * 300 < 1/512: snaps to -0
  v.local = {localFor(view, -0.0, -0.5, -1.0),  localFor(view, -0.5, -0.0, -2.0),
             localFor(view, -0.0, -0.0, -3.0),  localFor(view, -tiny, -1.0, -1.5),
             localFor(view, -1.0, -tiny, -0.5), localFor(view, 0.0, -0.25, -0.75)};
  return v;
}

// Identity pose, z = (2 - d) / 4 (exact here): depths exactly halfway between two floats whose
// lower one is even (nearest even: down) or odd (nearest even: up), from 2^-20 to just below 1.
VertexStageVector depthTies(Rng& rng, const View& view) {
  VertexStageVector v;
  v.name = std::string("depth_ties_") + view.name;
  v.transform.window = {view.axes, -1.0, 4.0, 640.0, -1.0, 4.0, 480.0, 2.0, 4.0};
  // m = (2 M + 1) 2^(e - 1): halfway between the floats M 2^e and (M + 1) 2^e.
  const auto tie = [](long long mantissa, int exponent) {
    return std::ldexp(static_cast<double>(2 * mantissa + 1), exponent - 1);
  };
  std::vector<double> ties = {tie((1LL << 24) - 1, -24)};  // 1 - 2^-25: up to 1
  for (int i = 0; i < 7; ++i) {
    long long mantissa = (1LL << 23) + rng.uniform(0, (1LL << 23) - 2);
    if ((mantissa & 1) != (i & 1))
      ++mantissa;
    ties.push_back(tie(mantissa, static_cast<int>(-24 - rng.uniform(0, 19))));
  }
  for (std::size_t i = 0; i < ties.size(); ++i) {
    const double u = static_cast<double>(i) * 0.375 - 0.5;
    v.local.push_back(localFor(view, u, 0.25 * static_cast<double>(i % 3), 2.0 - 4.0 * ties[i]));
  }
  return v;
}

// Identity pose, depthMax = 0, depthRange = 1.5: z = -d / 1.5, exact for z a multiple of
// 2^-151. Depths below the smallest normal float 2^-126: subnormal floats, ties between
// subnormals (lower even and odd), the tie between 0 and the smallest subnormal, a depth just
// below 2^-126 that rounds up to it, a random one; and one ordinary depth.
VertexStageVector subnormalDepths(Rng& rng, const View& view) {
  VertexStageVector v;
  v.name = std::string("depth_subnormal_") + view.name;
  v.transform.window = {view.axes, -1.0, 4.0, 640.0, -1.0, 4.0, 480.0, 0.0, 1.5};
  const double sub = 0x1p-149;                        // the smallest subnormal float
  const long long k = 2 * rng.uniform(1, 1LL << 21);  // even
  const std::vector<double> depths = {
      3.0 * sub,
      static_cast<double>(k) * sub + sub / 2.0,      // tie, lower even
      static_cast<double>(k + 1) * sub + sub / 2.0,  // tie, lower odd
      sub / 2.0,                                     // tie between 0 and the smallest
      0x1p-126 - 0x1p-151,                           // rounds up to the smallest normal
      between(rng, 0.05, 0.95) * 0x1p-126,
      0.5};
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const double u = static_cast<double>(i) * 0.5 - 0.75;
    v.local.push_back(
        localFor(view, u, 1.0 - 0.25 * static_cast<double>(i % 4), -(depths[i] * 1.5)));
  }
  return v;
}

void fillExpected(VertexStageVector& v) {
  for (const Vec3& p : v.local) {
    if (!raster::drawablePosition(position(v.transform, p)))
      throw std::logic_error("vertex-stage vectors: " + v.name + " has a vertex out of range");
    v.expected.push_back(raster::vertexStage(v.transform, p));
  }
}

}  // namespace

std::vector<VertexStageVector> vertexStageVectors() {
  std::vector<VertexStageVector> out;
  for (std::size_t view = 0; view < kViews.size(); ++view) {
    const View& w = kViews[view];
    // The aims through world axes: the x and y rows (rows_right_first), the z row, the others.
    const std::vector<Aim> aims = {{R::RowsRightFirst, 0},
                                   {R::RowsRightFirst, 1},
                                   {R::ZRowAsXY, 2},
                                   {R::TranslationFirst, 0},
                                   {R::TranslationFirst, 2},
                                   {R::FmaPose, 1},
                                   {R::FmaPose, 2},
                                   {R::WindowScaleFirst, w.axes[0]},
                                   {R::WindowMultiplyFirst, w.axes[1]},
                                   {R::DepthReciprocal, -1},
                                   {R::DepthFromMin, -1},
                                   {R::SnapAfterFloat, w.axes[0]},
                                   {R::SnapHalfAway, w.axes[1]},
                                   {R::SnapHalfUp, w.axes[0]}};
    for (int i = 0; i < 3; ++i) {
      out.push_back(rotatedBlock("rotated_" + std::string(w.name) + "_" + std::to_string(i),
                                 0x5eed0100 + 16 * view + static_cast<std::uint64_t>(i), w, 0.0,
                                 10.0, 3, aims));
    }
  }
  for (std::size_t view = 0; view < kViews.size(); ++view) {
    const View& w = kViews[view];
    // A block of size 1 to 4 some 10^3 to 10^5 away: t + l0 p0 rounds away most of the product.
    // Aimed at the translation added first only: the other orders of the sums and fusion change
    // the products' sum by an ulp of the block's size, which adding the translation rounds
    // away, and the window's other associations matter only within an ulp of a tie, which the
    // coarse grid of far world coordinates seldom comes near.
    const std::vector<Aim> aims = {{R::TranslationFirst, 0}, {R::TranslationFirst, 1},
                                   {R::TranslationFirst, 2}, {R::TranslationFirst, 0},
                                   {R::TranslationFirst, 1}, {R::TranslationFirst, 2}};
    out.push_back(
        rotatedBlock("far_" + std::string(w.name), 0x5eed0200 + view, w, 1e3, 1e5, 2, aims));
  }
  for (std::size_t view = 0; view < kViews.size(); ++view)
    out.push_back(snapTies(kViews[view], 1000.0 + 2.0 * static_cast<double>(view) * 1024.0));
  for (const View& w : kViews)
    out.push_back(signedZeros(w));
  for (std::size_t view = 0; view < kViews.size(); ++view) {
    Rng rng(0x5eed0300 + view);
    out.push_back(depthTies(rng, kViews[view]));
  }
  for (std::size_t view = 0; view < kViews.size(); ++view) {
    Rng rng(0x5eed0400 + view);
    out.push_back(subnormalDepths(rng, kViews[view]));
  }
  for (VertexStageVector& v : out)
    fillExpected(v);
  return out;
}

}  // namespace recode::kit
