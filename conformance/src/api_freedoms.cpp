// The states the graphics APIs allow in each pixel (api_freedoms.hpp): the stream followed with
// a set of states per pixel. The bounds below are written so that rounding in this file can
// only widen an interval, never narrow it: every width is a sound upper bound of what its
// freedom can move.

#include "recode/conformance/api_freedoms.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "contract_arithmetic.hpp"
#include "reading_class.hpp"

namespace recode::conformance {

namespace {

using contract::applyOp;
using contract::compare;
using contract::masked;
using contract::roundHalfEven;
using raster::CompareFunc;
using raster::StencilOp;

using contract::kDepthOne;
constexpr double kDepthScale = 16777215.0;
// What a vertex within the guaranteed bounds may still move besides snapping, in 24.8 units: a
// unit of the grid for the single-precision arithmetic that carries it to the rasterizer.
constexpr double kClipUnits = 1.0;
// What this file's own double arithmetic can be off by, relative to |z| (a few ulps, widened).
constexpr double kOwnRounding = 1e-12;

bool has(FreedomSet set, Freedom f) {
  return (set & static_cast<FreedomSet>(f)) != 0;
}

// A depth as an interval of 24-bit values. `sym` names the value when it is one unknown value
// that another fragment can also hold: the same triangle at the same sample gives the same
// depth every time it is drawn (the APIs' invariance rules), and the same clear value the same
// bits. 0: no such name.
struct DepthRange {
  std::uint32_t lo = kDepthOne, hi = kDepthOne;
  std::uint64_t sym = 0;
  FreedomSet freedoms = 0;  // what made it wider than one value
};

struct State {
  std::uint8_t stencil = 0;
  DepthRange depth;
  FreedomSet freedoms = 0;  // every freedom on the path to this state
};

// A pixel's states, at most one per stencil value (depths of one stencil value merge into the
// hull of their intervals).
class PixelStates {
 public:
  PixelStates() { states_.push_back(State{}); }
  [[nodiscard]] const std::vector<State>& states() const { return states_; }
  void replace(std::vector<State> next) {
    states_.clear();
    for (State& s : next)
      add(s);
  }

 private:
  void add(const State& s) {
    for (State& t : states_) {
      if (t.stencil != s.stencil)
        continue;
      const bool same =
          t.depth.sym == s.depth.sym && t.depth.lo == s.depth.lo && t.depth.hi == s.depth.hi;
      t.depth.lo = std::min(t.depth.lo, s.depth.lo);
      t.depth.hi = std::max(t.depth.hi, s.depth.hi);
      if (!same)
        t.depth.sym = 0;
      t.depth.freedoms |= s.depth.freedoms;
      t.freedoms |= s.freedoms;
      return;
    }
    states_.push_back(s);
  }
  std::vector<State> states_;
};

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  return h;
}

std::uint64_t floatBits(float f) {
  std::uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

std::uint32_t toDepth(double q) {
  return static_cast<std::uint32_t>(std::clamp(q, 0.0, kDepthScale));
}

// No freedom taken: the contract's grid and arithmetic, z to 24 bits to nearest. `convert` with
// these widths gives the values the contract's own rounding reaches, to tell whether a freedom
// widened a depth.
constexpr FreedomWidths kRoundToNearest{.subPixelBits = 8,
                                        .tieRule = true,
                                        .depthPrecision = 0.0,
                                        .depthConversion = false,
                                        .clipping = false};

// The 24-bit values z in [zlo, zhi] may convert to.
DepthRange convert(double zlo, double zhi, const FreedomWidths& w) {
  DepthRange r;
  const double slo = std::clamp(zlo, 0.0, 1.0) * kDepthScale;
  const double shi = std::clamp(zhi, 0.0, 1.0) * kDepthScale;
  const std::uint32_t nearLo = toDepth(roundHalfEven(slo));
  const std::uint32_t nearHi = toDepth(roundHalfEven(shi));
  if (w.depthConversion) {
    r.lo = toDepth(std::floor(slo));
    r.hi = toDepth(std::ceil(shi));
    if (r.lo != nearLo || r.hi != nearHi)
      r.freedoms |= static_cast<FreedomSet>(Freedom::DepthConversion);
  } else {
    r.lo = nearLo;
    r.hi = nearHi;
  }
  return r;
}

struct Outcomes {
  bool pass = false, fail = false;
};

// Whether `incoming FUNC stored` can pass and can fail for values in the two intervals.
Outcomes depthTest(CompareFunc f, const DepthRange& in, const DepthRange& st) {
  if ((in.sym != 0 && in.sym == st.sym) || (in.lo == in.hi && st.lo == st.hi)) {
    const bool r = in.sym != 0 && in.sym == st.sym ? compare(f, 0, 0) : compare(f, in.lo, st.lo);
    return {r, !r};
  }
  const bool overlap = in.lo <= st.hi && st.lo <= in.hi;
  const bool onlyEqual = in.lo == in.hi && st.lo == st.hi && in.lo == st.lo;
  switch (f) {
    case CompareFunc::Never:
      return {false, true};
    case CompareFunc::Always:
      return {true, false};
    case CompareFunc::Less:
      return {in.lo < st.hi, in.hi >= st.lo};
    case CompareFunc::LEqual:
      return {in.lo <= st.hi, in.hi > st.lo};
    case CompareFunc::Greater:
      return {in.hi > st.lo, in.lo <= st.hi};
    case CompareFunc::GEqual:
      return {in.hi >= st.lo, in.lo < st.hi};
    case CompareFunc::Equal:
      return {overlap, !onlyEqual};
    case CompareFunc::NotEqual:
      return {!onlyEqual, overlap};
  }
  return {true, true};
}

enum class Cover { No, Yes, Open };

// A triangle snapped to the contract's grid, with the bounds of what the freedoms can move.
struct Triangle {
  int command = 0, draw = 0, index = 0;
  long long X[3] = {0, 0, 0}, Y[3] = {0, 0, 0};
  float Z[3] = {0, 0, 0};
  long long a2 = 0;
  double snapUnits = 0;  // how far (24.8 units, per axis) snapping and clipping move a vertex
  bool clipped = false;  // a vertex lies beyond the guaranteed bounds: it may be clipped
  double areaReach = 0;  // a bound on how far that moves A2
  bool facingFixed = true;
  bool front = true;
  double zMin = 0, zMax = 0, zMagnitude = 0;
  std::uint64_t sym = 0;
};

// A bound on how far moving both ends of an edge by `d` per axis moves E = dx (yc - ya) -
// dy (xc - xa): dx and dy move by 2d, the sample's offsets from a by d.
double edgeReach(double d, long long dx, long long dy, long long ox, long long oy) {
  if (d == 0)
    return 0;
  return d * (2.0 * std::fabs(static_cast<double>(oy)) + 2.0 * std::fabs(static_cast<double>(ox)) +
              std::fabs(static_cast<double>(dx)) + std::fabs(static_cast<double>(dy))) +
         4.0 * d * d;
}

struct Coverage {
  Cover cover = Cover::No;
  Freedom freedom = Freedom::TieRule;  // the one the report names
  FreedomSet freedoms = 0;             // every freedom that opens it (a sample on an edge that
                                       // snapping can also move opens both)
  std::string how;                     // filled only when asked
};

std::string edgeText(int a, int b) {
  return "edge v" + std::to_string(a) + " -> v" + std::to_string(b);
}

std::string pixelsText(double units) {
  std::ostringstream o;
  o.precision(3);
  o << units / 256.0;
  return o.str();
}

// The cross product of (b - a) and (c - a), exactly.
long long cross(const Triangle& t, int a, int b, long long xc, long long yc) {
  return (t.X[b] - t.X[a]) * (yc - t.Y[a]) - (t.Y[b] - t.Y[a]) * (xc - t.X[a]);
}

Coverage coverage(const Triangle& t, long long xc, long long yc, const FreedomWidths& w,
                  bool explain) {
  Coverage out;
  const double d = t.snapUnits;
  if (!t.facingFixed) {
    // Snapping can flip or flatten the triangle: it covers the sample if it lies inside either
    // orientation of the moved edges.
    bool canNeg = true, canPos = true, onEdge = false;
    for (int k = 0; k < 3; ++k) {
      const int a = k, b = (k + 1) % 3;
      const long long e = cross(t, a, b, xc, yc);
      onEdge = onEdge || e == 0;
      const double r = edgeReach(d, t.X[b] - t.X[a], t.Y[b] - t.Y[a], xc - t.X[a], yc - t.Y[a]);
      if (static_cast<double>(e) - r > 0)
        canNeg = false;
      if (static_cast<double>(e) + r < 0)
        canPos = false;
    }
    if (!canNeg && !canPos)
      return out;
    out.cover = Cover::Open;
    const bool tie = onEdge && w.tieRule;
    out.freedom = tie ? Freedom::TieRule : Freedom::SubPixelPrecision;
    out.freedoms = static_cast<FreedomSet>(Freedom::SubPixelPrecision) |
                   (tie ? static_cast<FreedomSet>(Freedom::TieRule) : 0) |
                   (t.clipped ? static_cast<FreedomSet>(Freedom::Clipping) : 0);
    if (explain)
      out.how = std::string(tie ? "the sample lies exactly on an edge, and " : "") +
                "A2 = " + std::to_string(t.a2) + " lies within the reach of snapping" +
                (t.clipped ? " and clipping" : "") + " (" +
                std::to_string(static_cast<long long>(t.areaReach)) +
                "): the triangle may face either way or vanish";
    return out;
  }
  const int order[3] = {0, t.front ? 1 : 2, t.front ? 2 : 1};
  bool open = false;
  bool tieOnly = true;
  double nearest = std::numeric_limits<double>::infinity();
  int nearA = 0, nearB = 0;
  for (int k = 0; k < 3; ++k) {
    const int a = order[k], b = order[(k + 1) % 3];
    const long long dx = t.X[b] - t.X[a], dy = t.Y[b] - t.Y[a];
    const long long e = dx * (yc - t.Y[a]) - dy * (xc - t.X[a]);
    const double r = edgeReach(d, dx, dy, xc - t.X[a], yc - t.Y[a]);
    const double ed = static_cast<double>(e);
    if (ed + r < 0 || (r == 0 && e < 0))
      return out;  // outside for every allowed snapping
    if (ed - r > 0 || (r == 0 && e > 0))
      continue;  // inside this edge for every allowed snapping
    if (e == 0 && !w.tieRule && r == 0) {
      const bool inclusive = dy < 0 || (dy == 0 && dx > 0);
      if (!inclusive)
        return out;
      continue;
    }
    open = true;
    if (e != 0)
      tieOnly = false;
    out.freedoms |= static_cast<FreedomSet>(e == 0 && w.tieRule ? Freedom::TieRule
                                                                : Freedom::SubPixelPrecision);
    if (e != 0 && t.clipped)
      out.freedoms |= static_cast<FreedomSet>(Freedom::Clipping);
    const double dist =
        std::fabs(ed) / std::hypot(static_cast<double>(dx), static_cast<double>(dy));
    if (dist < nearest) {
      nearest = dist;
      nearA = a;
      nearB = b;
    }
  }
  if (!open) {
    out.cover = Cover::Yes;
    return out;
  }
  out.cover = Cover::Open;
  out.freedom = tieOnly && w.tieRule ? Freedom::TieRule : Freedom::SubPixelPrecision;
  if (explain) {
    if (out.freedom == Freedom::TieRule)
      out.how = "the sample lies exactly on " + edgeText(nearA, nearB);
    else
      out.how = "the sample lies " + pixelsText(nearest) + " pixels from " +
                edgeText(nearA, nearB) + ", within the " + pixelsText(d) +
                " pixels a vertex may move when snapped to " + std::to_string(w.subPixelBits) +
                " sub-pixel bits" +
                (t.clipped ? " and clipped in single precision beyond the viewport bounds" : "");
  }
  return out;
}

// An interval [lo, hi] divided by [dlo, dhi], which does not contain 0.
void divide(double lo, double hi, double dlo, double dhi, double& outLo, double& outHi) {
  const double c[4] = {lo / dlo, lo / dhi, hi / dlo, hi / dhi};
  outLo = *std::min_element(c, c + 4);
  outHi = *std::max_element(c, c + 4);
}

// How far the plane's arithmetic may move z at the sample when every operation is accurate to
// `rho` of its result (OpenGL's rule for floating-point computation), for the plane written as
// the contract writes it: z = z0 + (na (Xc - X0) + nb (Yc - Y0)) / A2, with na = dz1 e2y -
// dz2 e1y, nb = dz2 e1x - dz1 e2x. Each input's error is bounded by rho times the magnitude of
// the terms it is made of (so a difference that cancels keeps the error of its terms), and the
// bounds are carried through with interval arithmetic. Returns false when A2's error reaches
// A2 itself: then the arithmetic bounds nothing and z may be any value.
bool arithmeticReach(const Triangle& t, long long xc, long long yc, double rho, double& reach) {
  const double z0 = t.Z[0], z1 = t.Z[1], z2 = t.Z[2];
  const double dz1 = z1 - z0, dz2 = z2 - z0;
  const double dz1Err = rho * (std::fabs(z1) + std::fabs(z0));
  const double dz2Err = rho * (std::fabs(z2) + std::fabs(z0));
  const double e1x = static_cast<double>(t.X[1] - t.X[0]);
  const double e1y = static_cast<double>(t.Y[1] - t.Y[0]);
  const double e2x = static_cast<double>(t.X[2] - t.X[0]);
  const double e2y = static_cast<double>(t.Y[2] - t.Y[0]);
  const double a2 = static_cast<double>(t.a2);
  const double a2Err = rho * (std::fabs(e1x * e2y) + std::fabs(e2x * e1y)) * 2.0;
  if (a2Err >= std::fabs(a2) * 0.5)
    return false;
  const double na = dz1 * e2y - dz2 * e1y;
  const double nb = dz2 * e1x - dz1 * e2x;
  const double naErr = rho * (std::fabs(dz1 * e2y) + std::fabs(dz2 * e1y)) * 2.0 +
                       dz1Err * std::fabs(e2y) + dz2Err * std::fabs(e1y);
  const double nbErr = rho * (std::fabs(dz2 * e1x) + std::fabs(dz1 * e2x)) * 2.0 +
                       dz2Err * std::fabs(e1x) + dz1Err * std::fabs(e2x);
  const double dx = static_cast<double>(xc - t.X[0]);
  const double dy = static_cast<double>(yc - t.Y[0]);
  const double num = na * dx + nb * dy;
  const double numErr = naErr * std::fabs(dx) + nbErr * std::fabs(dy) +
                        rho * (std::fabs(na * dx) + std::fabs(nb * dy)) * 2.0;
  // |num'/a2' - num/a2| <= (numErr + |num/a2| a2Err) / (|a2| - a2Err)
  const double tExact = num / a2;
  const double tErr = (numErr + std::fabs(tExact) * a2Err) / (std::fabs(a2) - a2Err);
  reach = tErr + rho * 2.0 * (std::fabs(z0) + std::fabs(tExact) + tErr) + rho * std::fabs(z0);
  return true;
}

// The depth of a fragment of `t` at the sample, as the freedoms allow it. `inside`: the sample
// lies inside every triangle snapping can make, so z lies between the vertices' depths.
DepthRange fragmentDepth(const Triangle& t, long long xc, long long yc, bool inside,
                         const FreedomWidths& w) {
  double zlo = t.zMin, zhi = t.zMax;
  FreedomSet widened = 0;
  if (t.facingFixed) {
    // z = z0 + l1 (z1 - z0) + l2 (z2 - z0), lk = Nk / A2 with Nk the edge function of the edge
    // opposite vertex k: snapping moves every Nk and A2 within their reach. On a sample near an
    // edge the moved plane may be evaluated outside its triangle, so z is not held to the
    // vertices' depths there.
    const double d = t.snapUnits;
    double l[3][2];
    const int opp[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    const double a2 = static_cast<double>(t.a2);
    const double alo = a2 - t.areaReach;  // |A2| > its reach: the interval keeps A2's sign
    const double ahi = a2 + t.areaReach;
    for (int k = 0; k < 3; ++k) {
      const int a = opp[k][0], b = opp[k][1];
      const long long n = cross(t, a, b, xc, yc);
      const double r = edgeReach(d, t.X[b] - t.X[a], t.Y[b] - t.Y[a], xc - t.X[a], yc - t.Y[a]);
      divide(static_cast<double>(n) - r, static_cast<double>(n) + r, alo, ahi, l[k][0], l[k][1]);
    }
    const double z0 = t.Z[0];
    const double dz1 = static_cast<double>(t.Z[1]) - z0;
    const double dz2 = static_cast<double>(t.Z[2]) - z0;
    const double p1[2] = {l[1][0] * dz1, l[1][1] * dz1};
    const double p2[2] = {l[2][0] * dz2, l[2][1] * dz2};
    const double plo = z0 + std::min(p1[0], p1[1]) + std::min(p2[0], p2[1]);
    const double phi = z0 + std::max(p1[0], p1[1]) + std::max(p2[0], p2[1]);
    const double own =
        kOwnRounding * std::max({1e-30, t.zMagnitude, std::fabs(plo), std::fabs(phi)});
    if (inside) {
      zlo = std::max(zlo, plo - own);
      zhi = std::min(zhi, phi + own);
      if (zlo > zhi)  // rounding of the bounds themselves: fall back to the hull
        zlo = t.zMin, zhi = t.zMax;
    } else {
      zlo = plo - own;
      zhi = phi + own;
    }
    if (d > 0) {
      const DepthRange core = convert(zlo, zhi, kRoundToNearest);
      if (core.lo != core.hi)
        widened |= static_cast<FreedomSet>(Freedom::SubPixelPrecision);
    }
  } else {
    zlo = 0.0;  // a triangle that may flip or vanish: its plane bounds nothing
    zhi = 1.0;
    widened |= static_cast<FreedomSet>(Freedom::SubPixelPrecision);
  }
  if (t.clipped && w.clipping) {
    // The clipped polygon's fan interpolates, at a sample inside one of its triangles, the
    // depths its vertices got on the triangle's edges: any value between the vertices' depths,
    // each off by the float rounding of its interpolation.
    const double margin = 4.0 * std::ldexp(1.0, -24) * std::max(1.0, t.zMagnitude);
    const DepthRange before = convert(zlo, zhi, kRoundToNearest);
    zlo = std::min(zlo, t.zMin - margin);
    zhi = std::max(zhi, t.zMax + margin);
    const DepthRange after = convert(zlo, zhi, kRoundToNearest);
    if (after.lo != before.lo || after.hi != before.hi)
      widened |= static_cast<FreedomSet>(Freedom::Clipping);
  }
  const DepthRange nearest = convert(zlo, zhi, kRoundToNearest);
  if (w.depthPrecision > 0) {
    double reach = 0;
    if (t.facingFixed && arithmeticReach(t, xc, yc, w.depthPrecision, reach)) {
      zlo -= reach;
      zhi += reach;
    } else {
      zlo = 0.0;
      zhi = 1.0;
    }
  }
  DepthRange r = convert(zlo, zhi, w);
  const DepthRange interpolated = convert(zlo, zhi, kRoundToNearest);
  if (interpolated.lo != nearest.lo || interpolated.hi != nearest.hi)
    widened |= static_cast<FreedomSet>(Freedom::DepthInterpolation);
  r.freedoms |= widened;
  if (r.lo != r.hi)
    r.sym = t.sym;
  return r;
}

std::string depthText(const DepthRange& r) {
  if (r.lo == r.hi)
    return std::to_string(r.lo);
  return std::to_string(r.lo) + " .. " + std::to_string(r.hi);
}

// The freedom that names a choice several opened: the lowest rank of the table.
Freedom mainFreedom(FreedomSet s) {
  const FreedomInfo* best = nullptr;
  for (const FreedomInfo& i : allFreedoms())
    if (has(s, i.freedom) && (best == nullptr || i.rank < best->rank))
      best = &i;
  return best != nullptr ? best->freedom : Freedom::DepthInterpolation;
}

// Follows a stream over the pixels of one rectangle of the frame.
class Follower {
 public:
  Follower(const raster::CommandStream& stream, const FreedomWidths& widths, int x0, int y0, int x1,
           int y1, std::vector<OpenChoice>* choices)
      : stream_(stream), w_(widths), x0_(x0), y0_(y0), x1_(x1), y1_(y1), choices_(choices) {
    pixels_.resize(static_cast<std::size_t>(x1 - x0) * static_cast<std::size_t>(y1 - y0));
    st_ = raster::initialRenderState(stream.width, stream.height);
    snapUnits_ = widths.subPixelBits >= 8
                     ? 0.0
                     : std::ldexp(1.0, 8 - std::max(0, widths.subPixelBits)) + kClipUnits;
  }

  void run() {
    int draw = 0;
    for (std::size_t ci = 0; ci < stream_.commands.size(); ++ci) {
      const raster::Command& cmd = stream_.commands[ci];
      const int command = static_cast<int>(ci);
      if (raster::applyToState(cmd, st_, stream_.width, stream_.height))
        continue;
      if (const auto* cd = std::get_if<raster::cmd::ClearDepth>(&cmd)) {
        clearDepth(cd->value, command);
      } else if (const auto* cs = std::get_if<raster::cmd::ClearStencil>(&cmd)) {
        clearStencil(cs->value);
      } else if (const auto* dr = std::get_if<raster::cmd::Draw>(&cmd)) {
        drawTriangles(*dr, command, draw);
        ++draw;
      }
    }
  }

  [[nodiscard]] std::vector<AllowedPixel> result() const {
    std::vector<AllowedPixel> out(pixels_.size());
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
      for (const State& s : pixels_[i].states())
        out[i].states.push_back({s.stencil, s.depth.lo, s.depth.hi,
                                 static_cast<FreedomSet>(s.freedoms | s.depth.freedoms)});
      std::sort(out[i].states.begin(), out[i].states.end(),
                [](const AllowedState& a, const AllowedState& b) { return a.stencil < b.stencil; });
    }
    return out;
  }

 private:
  PixelStates& at(int x, int y) {
    return pixels_[static_cast<std::size_t>(y - y0_) * static_cast<std::size_t>(x1_ - x0_) +
                   static_cast<std::size_t>(x - x0_)];
  }

  // The scissor's pixels within the followed rectangle, as [xa, xb) x [ya, yb).
  bool scissorSpan(int& xa, int& ya, int& xb, int& yb) const {
    xa = std::max(x0_, st_.scissor.x0);
    ya = std::max(y0_, st_.scissor.y0);
    xb = std::min(x1_, st_.scissor.x1);
    yb = std::min(y1_, st_.scissor.y1);
    return xa < xb && ya < yb;
  }

  void clearDepth(double value, int command) {
    if (!std::isfinite(value))
      throw std::invalid_argument("allowedByApis: command " + std::to_string(command) +
                                  ": clear_depth value is not finite");
    if (!st_.depthWrite)
      return;
    DepthRange r = convert(value, value, w_);
    if (r.lo != r.hi) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &value, sizeof bits);
      r.sym = mix(0x636c656172ull, bits);
    }
    int xa, ya, xb, yb;
    if (!scissorSpan(xa, ya, xb, yb))
      return;
    for (int y = ya; y < yb; ++y)
      for (int x = xa; x < xb; ++x) {
        std::vector<State> next = at(x, y).states();
        for (State& s : next) {
          s.depth = r;
          s.freedoms |= r.freedoms;
        }
        at(x, y).replace(std::move(next));
      }
  }

  void clearStencil(std::uint8_t value) {
    int xa, ya, xb, yb;
    if (!scissorSpan(xa, ya, xb, yb))
      return;
    for (int y = ya; y < yb; ++y)
      for (int x = xa; x < xb; ++x) {
        std::vector<State> next = at(x, y).states();
        for (State& s : next)
          s.stencil = masked(value, s.stencil, st_.stencilWriteMask);
        at(x, y).replace(std::move(next));
      }
  }

  Triangle setUp(const raster::cmd::Draw& d, std::size_t ti, int command, int draw) const {
    Triangle t;
    t.command = command;
    t.draw = draw;
    t.index = static_cast<int>(ti);
    t.snapUnits = snapUnits_;
    std::uint64_t h = 0x747269ull;
    for (std::size_t k = 0; k < 3; ++k) {
      const raster::WindowVertex& v = d.vertices[d.indices[3 * ti + k]];
      t.X[k] = contract::snap(v.x);
      t.Y[k] = contract::snap(v.y);
      t.Z[k] = v.z;
      h = mix(mix(mix(h, static_cast<std::uint64_t>(t.X[k])), static_cast<std::uint64_t>(t.Y[k])),
              floatBits(v.z));
    }
    t.sym = h | 1;  // never 0
    if (w_.clipping) {
      // Beyond the bounds every API rasterizes whole, the clip's new vertices lie off the
      // triangle's edges by its rounding, relative to the coordinates' size.
      const ViewportBounds bounds = guaranteedBounds(std::max(stream_.width, stream_.height));
      double size = std::max(stream_.width, stream_.height);
      for (std::size_t k = 0; k < 3; ++k) {
        const raster::WindowVertex& v = d.vertices[d.indices[3 * ti + k]];
        for (const double c : {static_cast<double>(v.x), static_cast<double>(v.y)}) {
          t.clipped = t.clipped || c < bounds.lo || c > bounds.hi;
          size = std::max(size, std::fabs(c));
        }
      }
      if (t.clipped)
        t.snapUnits += 256.0 * kClipRounding * 2.0 * size;
    }
    t.a2 = (t.X[1] - t.X[0]) * (t.Y[2] - t.Y[0]) - (t.X[2] - t.X[0]) * (t.Y[1] - t.Y[0]);
    const double dd = t.snapUnits;
    if (dd > 0) {
      const double e[4] = {
          static_cast<double>(t.X[1] - t.X[0]), static_cast<double>(t.Y[2] - t.Y[0]),
          static_cast<double>(t.X[2] - t.X[0]), static_cast<double>(t.Y[1] - t.Y[0])};
      t.areaReach =
          2.0 * dd * (std::fabs(e[0]) + std::fabs(e[1]) + std::fabs(e[2]) + std::fabs(e[3])) +
          8.0 * dd * dd;
    }
    t.facingFixed = std::fabs(static_cast<double>(t.a2)) > t.areaReach;
    t.front = t.a2 > 0;
    t.zMin = std::min(
        {static_cast<double>(t.Z[0]), static_cast<double>(t.Z[1]), static_cast<double>(t.Z[2])});
    t.zMax = std::max(
        {static_cast<double>(t.Z[0]), static_cast<double>(t.Z[1]), static_cast<double>(t.Z[2])});
    t.zMagnitude = std::max(std::fabs(t.zMin), std::fabs(t.zMax));
    return t;
  }

  void drawTriangles(const raster::cmd::Draw& d, int command, int draw) {
    contract::validateDraw("allowedByApis", d, command);
    for (std::size_t ti = 0; ti < d.indices.size() / 3; ++ti) {
      const Triangle t = setUp(d, ti, command, draw);
      if (t.a2 == 0 && t.areaReach == 0)
        continue;  // degenerate on every allowed grid: draws nothing
      // The facings a fragment may have, after culling.
      bool facings[2] = {false, false};  // [0] back, [1] front
      if (t.facingFixed) {
        facings[t.front ? 1 : 0] = !st_.culls(t.front);
      } else {
        facings[1] = !st_.culls(true);
        facings[0] = !st_.culls(false);
      }
      if (!facings[0] && !facings[1])
        continue;
      int xa, ya, xb, yb;
      if (!scissorSpan(xa, ya, xb, yb))
        continue;
      // The pixels whose sample a moved vertex can reach: the bounding box grown by the reach.
      const double grow = t.snapUnits;
      const double minX = static_cast<double>(std::min({t.X[0], t.X[1], t.X[2]})) - grow;
      const double maxX = static_cast<double>(std::max({t.X[0], t.X[1], t.X[2]})) + grow;
      const double minY = static_cast<double>(std::min({t.Y[0], t.Y[1], t.Y[2]})) - grow;
      const double maxY = static_cast<double>(std::max({t.Y[0], t.Y[1], t.Y[2]})) + grow;
      // Sample (256 x + 128) within [min, max]: x within [(min - 128) / 256, (max - 128) / 256].
      xa = std::max(xa, static_cast<int>(std::ceil((minX - 128.0) / 256.0)));
      xb = std::min(xb, static_cast<int>(std::floor((maxX - 128.0) / 256.0)) + 1);
      ya = std::max(ya, static_cast<int>(std::ceil((minY - 128.0) / 256.0)));
      yb = std::min(yb, static_cast<int>(std::floor((maxY - 128.0) / 256.0)) + 1);
      // A clipped triangle thin enough for the clip's rounding to turn it over gives a polygon
      // that may fold over itself: two of its fan's triangles, of either facing, may cover the
      // sample, each with a depth of its own (no name shared: the second is another triangle).
      Triangle fold = t;
      fold.sym = 0;
      const bool folds = t.clipped && !t.facingFixed;
      for (int y = ya; y < yb; ++y)
        for (int x = xa; x < xb; ++x) {
          fragment(t, facings, x, y);
          if (folds)
            fragment(fold, facings, x, y);
        }
    }
  }

  void note(const Triangle& t, Freedom f, std::string how) {
    if (choices_ == nullptr)
      return;
    // A folding clipped triangle's second fragment opens the same choice: told once.
    if (!choices_->empty() && choices_->back().command == t.command &&
        choices_->back().triangle == t.index && choices_->back().how == how)
      return;
    choices_->push_back({t.command, t.draw, t.index, f, std::move(how)});
  }

  void fragment(const Triangle& t, const bool facings[2], int x, int y) {
    const long long xc = 256LL * x + 128, yc = 256LL * y + 128;
    const Coverage c = coverage(t, xc, yc, w_, choices_ != nullptr);
    if (c.cover == Cover::No)
      return;
    const FreedomSet coverFreedom = c.cover == Cover::Open ? c.freedoms : FreedomSet{0};
    if (c.cover == Cover::Open)
      note(t, c.freedom, c.how);
    const DepthRange z = fragmentDepth(t, xc, yc, c.cover == Cover::Yes, w_);
    std::vector<State> next;
    bool testOpened = false;
    FreedomSet testFreedoms = 0;
    DepthRange openStored;
    for (const State& s : at(x, y).states()) {
      if (c.cover == Cover::Open) {
        State kept = s;
        kept.freedoms |= coverFreedom;
        next.push_back(kept);
      }
      for (int face = 0; face < 2; ++face) {
        if (!facings[face])
          continue;
        const raster::StencilOps& ops = st_.opsFor(face == 1);
        State base = s;
        base.freedoms |= coverFreedom;
        if (!t.facingFixed)
          base.freedoms |= static_cast<FreedomSet>(Freedom::SubPixelPrecision);
        const bool stencilPasses = compare(
            st_.stencilFunc, static_cast<std::uint32_t>(st_.stencilRef & st_.stencilValueMask),
            static_cast<std::uint32_t>(s.stencil & st_.stencilValueMask));
        if (!stencilPasses) {
          State f = base;
          f.stencil = masked(applyOp(ops.stencilFail, s.stencil, st_.stencilRef), s.stencil,
                             st_.stencilWriteMask);
          next.push_back(f);
          continue;
        }
        const Outcomes o = depthTest(st_.depthFunc, z, s.depth);
        FreedomSet both = 0;
        if (o.pass && o.fail) {
          both = z.freedoms | s.depth.freedoms;
          if (both == 0)  // intervals from the freedoms only ever overlap through them
            both = static_cast<FreedomSet>(Freedom::DepthInterpolation);
          if (!testOpened) {
            testOpened = true;
            testFreedoms = both;
            openStored = s.depth;
          }
        }
        if (o.pass) {
          State p = base;
          p.freedoms |= both;
          p.stencil = masked(applyOp(ops.depthPass, s.stencil, st_.stencilRef), s.stencil,
                             st_.stencilWriteMask);
          if (st_.depthWrite)
            p.depth = z;
          next.push_back(p);
        }
        if (o.fail) {
          State f = base;
          f.freedoms |= both;
          f.stencil = masked(applyOp(ops.depthFail, s.stencil, st_.stencilRef), s.stencil,
                             st_.stencilWriteMask);
          next.push_back(f);
        }
      }
    }
    if (testOpened)
      note(t, mainFreedom(testFreedoms),
           "the depth test " + std::string(raster::toString(st_.depthFunc)) +
               " goes either way: the fragment's depth may be " + depthText(z) +
               " and the stored one " + depthText(openStored) + " (" + describe(testFreedoms) +
               ")");
    at(x, y).replace(std::move(next));
  }

  const raster::CommandStream& stream_;
  FreedomWidths w_;
  int x0_, y0_, x1_, y1_;
  std::vector<OpenChoice>* choices_;
  raster::RenderState st_;
  double snapUnits_ = 0;
  std::vector<PixelStates> pixels_;
};

void checkFrame(const raster::CommandStream& stream) {
  contract::checkFrameSize("allowedByApis", stream.width, stream.height);
}

}  // namespace

namespace {

constexpr FreedomInfo kFreedoms[] = {
#define RECODE_FREEDOM_ROW(e, bit, name, clause, rank) {Freedom::e, name, clause, rank},
    RECODE_CONFORMANCE_FREEDOMS(RECODE_FREEDOM_ROW)
#undef RECODE_FREEDOM_ROW
};

const FreedomInfo& infoOf(Freedom f) {
  for (const FreedomInfo& i : kFreedoms)
    if (i.freedom == f)
      return i;
  return kFreedoms[0];  // unreached: every enumerator is a row
}

}  // namespace

std::span<const FreedomInfo> allFreedoms() {
  return kFreedoms;
}

std::string_view toString(Freedom f) {
  return infoOf(f).name;
}

std::string_view apiClause(Freedom f) {
  return infoOf(f).clause;
}

std::vector<std::string> namesOf(FreedomSet set) {
  std::vector<std::string> out;
  for (const FreedomInfo& i : kFreedoms)
    if (has(set, i.freedom))
      out.emplace_back(i.name);
  return out;
}

std::optional<Freedom> freedomOf(kit::Variant v) {
  return classOf(v).freedom;
}

std::string describe(FreedomSet set) {
  std::string out;
  for (const std::string& name : namesOf(set))
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

bool AllowedPixel::stencilFixed() const {
  return states.size() == 1;
}

bool AllowedPixel::depthFixed() const {
  return !states.empty() && depthMin() == depthMax();
}

bool AllowedPixel::allowsStencil(std::uint8_t s) const {
  return std::any_of(states.begin(), states.end(),
                     [&](const AllowedState& a) { return a.stencil == s; });
}

bool AllowedPixel::allowsDepth(std::uint32_t d) const {
  return std::any_of(states.begin(), states.end(),
                     [&](const AllowedState& a) { return a.depthLo <= d && d <= a.depthHi; });
}

bool AllowedPixel::allows(std::uint32_t d, std::uint8_t s) const {
  return std::any_of(states.begin(), states.end(), [&](const AllowedState& a) {
    return a.stencil == s && a.depthLo <= d && d <= a.depthHi;
  });
}

FreedomSet AllowedPixel::freedomsFor(std::uint32_t d, std::uint8_t s) const {
  FreedomSet out = 0;
  for (const AllowedState& a : states)
    if (a.stencil == s && a.depthLo <= d && d <= a.depthHi)
      out |= a.freedoms;
  return out;
}

std::uint32_t AllowedPixel::depthMin() const {
  std::uint32_t m = kDepthOne;
  for (const AllowedState& a : states)
    m = std::min(m, a.depthLo);
  return m;
}

std::uint32_t AllowedPixel::depthMax() const {
  std::uint32_t m = 0;
  for (const AllowedState& a : states)
    m = std::max(m, a.depthHi);
  return m;
}

const AllowedPixel& AllowedFrame::at(int x, int y) const {
  return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)];
}

bool AllowedFrame::stencilRequired() const {
  return std::all_of(pixels.begin(), pixels.end(),
                     [](const AllowedPixel& p) { return p.stencilFixed(); });
}

bool AllowedFrame::depthRequired() const {
  return std::all_of(pixels.begin(), pixels.end(),
                     [](const AllowedPixel& p) { return p.depthFixed(); });
}

AllowedFrame allowedByApis(const raster::CommandStream& stream, const FreedomWidths& widths) {
  checkFrame(stream);
  Follower f(stream, widths, 0, 0, stream.width, stream.height, nullptr);
  f.run();
  return {stream.width, stream.height, f.result()};
}

AllowedPixel allowedAt(const raster::CommandStream& stream, int x, int y,
                       std::vector<OpenChoice>* choices, const FreedomWidths& widths) {
  checkFrame(stream);
  if (x < 0 || x >= stream.width || y < 0 || y >= stream.height)
    throw std::invalid_argument("allowedAt: pixel (" + std::to_string(x) + ", " +
                                std::to_string(y) + ") lies outside the frame");
  Follower f(stream, widths, x, y, x + 1, y + 1, choices);
  f.run();
  return f.result().front();
}

}  // namespace recode::conformance
