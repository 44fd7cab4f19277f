// The Embree oracle's bookkeeping: which pixels to examine, the intervals from the ray casts
// (with a brute-force fallback where a float hit is in doubt), and the classification of every
// disagreement with the device. docs/verification.md ("Embree") explains the rules.

#include "recode/verify/embree_oracle.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "embree_ray_caster.hpp"
#include "embree_window_block.hpp"

namespace recode::verify {

using detail::centreFixed;
using detail::PixelXY;
using detail::WindowBlock;

std::string_view toString(DisagreementKind kind) {
  switch (kind) {
    case DisagreementKind::Edge:
      return "edge";
    case DisagreementKind::Tie:
      return "tie";
    case DisagreementKind::Unexplained:
      break;
  }
  return "unexplained";
}

bool caseWithinTolerance(const std::optional<core::DepthInterval>& a,
                         const std::optional<core::DepthInterval>& b, int deviceCase,
                         std::uint32_t tolerance) {
  constexpr std::uint32_t kMaxTolerance = 8;  // 17^4 = 83521 combinations at most
  if (tolerance > kMaxTolerance) {
    std::ostringstream m;
    m << "depth tolerance " << tolerance << " is above the " << kMaxTolerance
      << " steps whose perturbations can be enumerated";
    throw std::invalid_argument(m.str());
  }
  if (deviceCase < kOutsideMor || deviceCase >= core::kCaseCount) {
    std::ostringstream m;
    m << "device case " << deviceCase << " is not a case (0-8, or " << kOutsideMor
      << " for outside the MOR)";
    throw std::invalid_argument(m.str());
  }
  const auto matches = [deviceCase](int c) {
    return deviceCase == kOutsideMor ? !core::isInterfering(c) : c == deviceCase;
  };
  // Depth cannot move a block's presence: without both blocks there is one case only.
  if (!a || !b)
    return matches(core::caseFromIntervals(a, b));
  const auto moved = [](std::uint32_t v, int delta) {
    const long long w = static_cast<long long>(v) + delta;
    return static_cast<std::uint32_t>(std::clamp<long long>(w, 0, raster::kDepthMax));
  };
  const int t = static_cast<int>(tolerance);
  for (int d0 = -t; d0 <= t; ++d0)
    for (int d1 = -t; d1 <= t; ++d1)
      for (int d2 = -t; d2 <= t; ++d2)
        for (int d3 = -t; d3 <= t; ++d3) {
          const core::DepthInterval pa{moved(a->min, d0), moved(a->max, d1)};
          const core::DepthInterval pb{moved(b->min, d2), moved(b->max, d3)};
          if (matches(core::caseFromIntervals(pa, pb)))
            return true;
        }
  return false;
}

namespace {

core::OrthoView pairView(const core::FrameSpec& frame, const core::TriangleMesh& a,
                         const core::TriangleMesh& b) {
  const auto [lo, hi] =
      core::pairDepthRange(frame.axis, core::boundingBox(a), core::boundingBox(b));
  return core::OrthoView(frame.axis, frame.window, frame.width, frame.height, lo, hi);
}

// The quantised entry and exit of one block at each pixel. Embree's float hits are trusted
// only when they are what a closed convex block must give: nothing on both rays, or an entry
// on a front-facing triangle and an exit on a back-facing one, both containing the pixel
// centre exactly and the entry no deeper than the exit. Anything else is settled by testing
// every triangle.
struct IntervalPass {
  detail::RayCaster& caster;
  std::vector<std::int32_t> entry, exit;
  long long rays = 0;

  void run(const WindowBlock& block, std::span<const PixelXY> pixels,
           std::vector<std::optional<core::DepthInterval>>& out,
           std::vector<std::uint8_t>& fellBack) {
    rays += caster.cast(block, pixels, entry, exit);
    out.assign(pixels.size(), std::nullopt);
    for (std::size_t k = 0; k < pixels.size(); ++k) {
      const std::int64_t px = centreFixed(pixels[k].x), py = centreFixed(pixels[k].y);
      const std::int32_t e = entry[k], x = exit[k];
      std::optional<std::array<double, 2>> interval;
      bool trusted = e == detail::kNoHit && x == detail::kNoHit;
      if (e != detail::kNoHit && x != detail::kNoHit) {
        const auto te = static_cast<std::size_t>(e), tx = static_cast<std::size_t>(x);
        if (block.area2[te] > 0 && block.area2[tx] < 0 && detail::covers(block, te, px, py) &&
            detail::covers(block, tx, px, py)) {
          const double near = detail::depthAt(block, te, px, py);
          const double far = detail::depthAt(block, tx, px, py);
          if (near <= far) {
            trusted = true;
            interval = std::array<double, 2>{near, far};
          }
        }
      }
      if (!trusted) {
        interval = detail::bruteForceInterval(block, px, py);
        fellBack[k] = 1;
      }
      if (interval)
        out[k] = core::DepthInterval{detail::quantiseDepth((*interval)[0]),
                                     detail::quantiseDepth((*interval)[1])};
    }
  }
};

void requireResultFits(const core::FrameSpec& frame, const core::PairResult& r) {
  const raster::PixelRect& m = r.mor;
  std::ostringstream msg;
  if (!m.empty() && (m.x0 < 0 || m.y0 < 0 || m.x1 > frame.width || m.y1 > frame.height)) {
    msg << "pair result's MOR [" << m.x0 << ", " << m.y0 << ", " << m.x1 << ", " << m.y1
        << "] does not lie in the " << frame.width << "x" << frame.height << " frame";
  } else if (static_cast<long long>(r.caseMap.data.size()) != m.area() ||
             (!m.empty() && r.caseMap.rect != m)) {
    msg << "pair result's case map has " << r.caseMap.data.size() << " pixels but its MOR has "
        << m.area();
  } else {
    for (std::size_t i = 0; i < r.caseMap.data.size(); ++i) {
      if (r.caseMap.data[i] >= core::kCaseCount) {
        msg << "pair result's case map holds " << int{r.caseMap.data[i]} << " at index " << i
            << " (cases are 0-8)";
        break;
      }
    }
  }
  if (!msg.str().empty())
    throw std::invalid_argument(msg.str());
}

// A result whose depth range is not the one these blocks give was computed for another pair:
// comparing its cases with these blocks' intervals would report nonsense as disagreements.
void requireSameDepthRange(const core::OrthoView& view, const core::PairResult& result) {
  if (view.depthMin() != result.depthMin || view.depthMax() != result.depthMax) {
    std::ostringstream m;
    m << "pair result maps depth over [" << result.depthMin << ", " << result.depthMax
      << "] but these blocks span [" << view.depthMin() << ", " << view.depthMax()
      << "] along the view axis: the result belongs to another pair";
    throw std::invalid_argument(m.str());
  }
}

// The MOR, where the device gives a case, then every pixel outside it whose centre lies in
// both blocks' footprints, where the device's answer is "not interfering". No pixel outside
// both footprints can hold both blocks. Fills `pixels` and returns the device's case at each
// (kOutsideMor outside the MOR).
std::vector<int> pixelsToExamine(const core::FrameSpec& frame, const WindowBlock& blockA,
                                 const WindowBlock& blockB, const core::PairResult& result,
                                 std::vector<PixelXY>& pixels) {
  const raster::PixelRect& mor = result.mor;
  const raster::PixelRect overlap =
      detail::footprint(blockA, frame.width, frame.height)
          .intersect(detail::footprint(blockB, frame.width, frame.height));
  pixels.clear();
  std::vector<int> deviceCases;
  for (int y = mor.y0; y < mor.y1; ++y)
    for (int x = mor.x0; x < mor.x1; ++x)
      pixels.push_back({x, y});
  deviceCases.assign(result.caseMap.data.begin(), result.caseMap.data.end());
  for (int y = overlap.y0; y < overlap.y1; ++y)
    for (int x = overlap.x0; x < overlap.x1; ++x)
      if (!result.caseMap.contains(x, y)) {
        pixels.push_back({x, y});
        deviceCases.push_back(kOutsideMor);
      }
  return deviceCases;
}

// Counts every pixel as an agreement, an edge, a tie or an unexplained disagreement, in that
// order of precedence, and lists the first unexplained ones.
void classifyPixels(std::span<const PixelXY> pixels,
                    const std::vector<std::optional<core::DepthInterval>>& a,
                    const std::vector<std::optional<core::DepthInterval>>& b,
                    const std::vector<int>& deviceCases, const WindowBlock& blockA,
                    const WindowBlock& blockB, EmbreeReport& report) {
  EmbreeCounts& c = report.counts;
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    ++c.pixels;
    const int oracleCase = core::caseFromIntervals(a[k], b[k]);
    const int deviceCase = deviceCases[k];
    const bool agree =
        deviceCase == kOutsideMor ? !core::isInterfering(oracleCase) : deviceCase == oracleCase;
    if (agree) {
      ++c.agree;
      continue;
    }
    const std::int64_t px = centreFixed(pixels[k].x), py = centreFixed(pixels[k].y);
    // Coverage first: at an edge sample the fill rule and Embree's float test may both be
    // right and still differ, and nothing about depth can be concluded there.
    if (detail::nearProjectedEdge(blockA, px, py) || detail::nearProjectedEdge(blockB, px, py)) {
      ++c.edges;
      continue;
    }
    if (caseWithinTolerance(a[k], b[k], deviceCase, kEmbreeDepthTolerance)) {
      ++c.ties;
      continue;
    }
    ++c.unexplained;
    if (report.unexplained.size() < kMaxListedDisagreements)
      report.unexplained.push_back({pixels[k].x, pixels[k].y, deviceCase, oracleCase,
                                    DisagreementKind::Unexplained, a[k], b[k]});
  }
}

}  // namespace

struct EmbreeOracle::Impl {
  detail::RayCaster caster;
  std::vector<PixelXY> pixels;
  std::vector<std::optional<core::DepthInterval>> a, b;
  std::vector<std::uint8_t> fellBack;

  // Intervals of both blocks at `pixels`; returns the rays cast and counts fallback pixels.
  long long intervals(const WindowBlock& blockA, const WindowBlock& blockB,
                      long long& fallbackPixels) {
    fellBack.assign(pixels.size(), 0);
    IntervalPass pass{caster, {}, {}, 0};
    pass.run(blockA, pixels, a, fellBack);
    pass.run(blockB, pixels, b, fellBack);
    fallbackPixels += std::count(fellBack.begin(), fellBack.end(), std::uint8_t{1});
    return pass.rays;
  }
};

EmbreeOracle::EmbreeOracle() : impl_(std::make_unique<Impl>()) {}
EmbreeOracle::~EmbreeOracle() = default;
EmbreeOracle::EmbreeOracle(EmbreeOracle&&) noexcept = default;
EmbreeOracle& EmbreeOracle::operator=(EmbreeOracle&&) noexcept = default;

EmbreeReport EmbreeOracle::check(const core::FrameSpec& frame, const core::TriangleMesh& worldA,
                                 const core::TriangleMesh& worldB, const core::PairResult& result) {
  requireResultFits(frame, result);
  const core::OrthoView view = pairView(frame, worldA, worldB);
  requireSameDepthRange(view, result);
  const WindowBlock blockA = detail::makeWindowBlock(view, worldA, "A");
  const WindowBlock blockB = detail::makeWindowBlock(view, worldB, "B");
  Impl& s = *impl_;
  const std::vector<int> deviceCases = pixelsToExamine(frame, blockA, blockB, result, s.pixels);
  EmbreeReport report;
  report.rays = s.intervals(blockA, blockB, report.fallbackPixels);
  classifyPixels(s.pixels, s.a, s.b, deviceCases, blockA, blockB, report);
  return report;
}

EmbreeSamples EmbreeOracle::sample(const core::FrameSpec& frame, const core::TriangleMesh& worldA,
                                   const core::TriangleMesh& worldB,
                                   const raster::PixelRect& rect) {
  const core::OrthoView view = pairView(frame, worldA, worldB);
  const WindowBlock blockA = detail::makeWindowBlock(view, worldA, "A");
  const WindowBlock blockB = detail::makeWindowBlock(view, worldB, "B");
  EmbreeSamples out;
  out.rect = rect.intersect({0, 0, frame.width, frame.height});
  Impl& s = *impl_;
  s.pixels.clear();
  for (int y = out.rect.y0; y < out.rect.y1; ++y)
    for (int x = out.rect.x0; x < out.rect.x1; ++x)
      s.pixels.push_back({x, y});
  out.rays = s.intervals(blockA, blockB, out.fallbackPixels);
  out.a = s.a;
  out.b = s.b;
  out.cases.resize(s.pixels.size());
  out.nearEdge.resize(s.pixels.size());
  for (std::size_t k = 0; k < s.pixels.size(); ++k) {
    out.cases[k] = static_cast<std::uint8_t>(core::caseFromIntervals(s.a[k], s.b[k]));
    const std::int64_t px = centreFixed(s.pixels[k].x), py = centreFixed(s.pixels[k].y);
    out.nearEdge[k] = static_cast<std::uint8_t>(detail::nearProjectedEdge(blockA, px, py) ||
                                                detail::nearProjectedEdge(blockB, px, py));
  }
  return out;
}

EmbreeReport checkCasesWithEmbree(const core::FrameSpec& frame, const core::TriangleMesh& worldA,
                                  const core::TriangleMesh& worldB,
                                  const core::PairResult& result) {
  EmbreeOracle oracle;
  return oracle.check(frame, worldA, worldB, result);
}

}  // namespace recode::verify
