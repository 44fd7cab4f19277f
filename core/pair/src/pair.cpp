#include "recode/pair/pair.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "recode/raster/fixed_point.hpp"
#include "recode/raster/pixel_buffer.hpp"
#include "recode/raster/state.hpp"

#include "block_window_source.hpp"
#include "pair_passes.hpp"
#include "pair_stages.hpp"

namespace recode::core {

namespace {

using detail::Clock;
using detail::microsecondsSince;
using raster::CullMode;
using raster::PixelRect;

// Quantised depth range of a block's vertices. Every fragment depth of the block lies in it
// up to rounding of the plane evaluation, hence the one-LSB slack where it is used.
struct DepthSpan {
  std::uint32_t min = raster::kDepthMax;
  std::uint32_t max = 0;
};

DepthSpan depthSpan(std::span<const raster::WindowVertex> vertices) {
  DepthSpan s;
  for (const raster::WindowVertex& v : vertices) {
    const std::uint32_t q = raster::quantizeDepth(v.z);
    s.min = std::min(s.min, q);
    s.max = std::max(s.max, q);
  }
  return s;
}

bool depthSpansMeet(const DepthSpan& a, const DepthSpan& b) {
  return a.min <= b.max + 1 && b.min <= a.max + 1;
}

// caseFromStencil for every byte, so decoding a large MOR is one table load per pixel.
const std::array<std::uint8_t, 256>& caseTable() {
  static const std::array<std::uint8_t, 256> table = [] {
    std::array<std::uint8_t, 256> t{};
    for (int s = 0; s < 256; ++s)
      t[static_cast<std::size_t>(s)] =
          static_cast<std::uint8_t>(caseFromStencil(static_cast<std::uint8_t>(s)));
    return t;
  }();
  return table;
}

PixelRect boundingRect(const PixelRect& a, const PixelRect& b) {
  if (a.empty())
    return b;
  if (b.empty())
    return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

}  // namespace

std::string_view toString(MorMode mode) {
  switch (mode) {
    case MorMode::Min:
      return "min";
    case MorMode::Max:
      return "max";
    case MorMode::Full:
      return "full";
  }
  return "?";
}

std::optional<MorMode> parseMorMode(std::string_view name) {
  for (const MorMode mode : {MorMode::Min, MorMode::Max, MorMode::Full})
    if (name == toString(mode))
      return mode;
  return std::nullopt;
}

std::string_view toString(PairStep step) {
  switch (step) {
    case PairStep::SetZ:
      return "set_z";
    case PairStep::TestZ:
      return "test_z";
    case PairStep::LoadAmin:
      return "load_amin";
    case PairStep::TestAminFront:
      return "test_amin_front";
    case PairStep::TestAminBack:
      return "test_amin_back";
    case PairStep::ReadStencil:
      return "read_stencil";
    case PairStep::ContactNear:
      return "contact_near";
    case PairStep::ContactFar:
      return "contact_far";
  }
  return "?";
}

std::array<double, 2> pairDepthRange(ViewAxis axis, const Aabb& a, const Aabb& b) {
  const int k = axis == ViewAxis::X ? 0 : axis == ViewAxis::Y ? 1 : 2;
  return {std::min(a.min[k], b.min[k]), std::max(a.max[k], b.max[k])};
}

PixelRect pixelFootprint(std::span<const raster::WindowVertex> vertices, int width, int height) {
  if (vertices.empty())
    return {};
  float xmin = vertices[0].x, xmax = xmin, ymin = vertices[0].y, ymax = ymin;
  for (const raster::WindowVertex& v : vertices) {
    xmin = std::min(xmin, v.x);
    xmax = std::max(xmax, v.x);
    ymin = std::min(ymin, v.y);
    ymax = std::max(ymax, v.y);
  }
  // Pixel i's centre i + 0.5 lies in [min, max] for ceil(min - 0.5) <= i <= floor(max - 0.5).
  // The snapped coordinates are multiples of 1/256, so these differences are exact.
  const auto first = [](float lo) { return static_cast<int>(std::ceil(double{lo} - 0.5)); };
  const auto last = [](float hi) { return static_cast<int>(std::floor(double{hi} - 0.5)) + 1; };
  const PixelRect frame{0, 0, width, height};
  return PixelRect{first(xmin), first(ymin), last(xmax), last(ymax)}.intersect(frame);
}

namespace detail {

void requireDeviceSize(const raster::DepthStencilDevice& device, const FrameSpec& frame) {
  if (device.width() != frame.width || device.height() != frame.height) {
    std::ostringstream m;
    m << "device is " << device.width() << "x" << device.height() << " but the pair's frame is "
      << frame.width << "x" << frame.height;
    throw std::invalid_argument(m.str());
  }
}

// The rectangle the passes run over (the paper's Table 1). MIN is empty when the footprints do
// not overlap; MAX only when both blocks lie off the frame.
PixelRect chooseMor(MorMode mode, const PixelRect& footA, const PixelRect& footB,
                    const FrameSpec& frame) {
  switch (mode) {
    case MorMode::Min:
      return footA.intersect(footB);
    case MorMode::Max:
      return boundingRect(footA, footB);
    case MorMode::Full:
      break;
  }
  return {0, 0, frame.width, frame.height};
}

// Adds a stencil's case counts to r's, and its interfering pixels (cases 3-6).
void addCaseCounts(const std::array<long long, kCaseCount>& counts, PairResult& r) {
  for (std::size_t c = 0; c < kCaseCount; ++c)
    r.caseCounts[c] += counts[c];
  for (int c = 3; c <= 6; ++c)
    r.interferingPixels += counts[static_cast<std::size_t>(c)];
}

// The verdict, the contact's pixel count and its area from the interfering pixels.
void concludeVerdict(const OrthoView& view, PairResult& r) {
  r.collide = r.interferingPixels > 0;
  r.contact.pixels = r.interferingPixels;
  r.contact.area =
      static_cast<double>(r.interferingPixels) * view.pixelWidth() * view.pixelHeight();
}

// Decodes the stencil read over the MOR into the case map and the case counts, and returns the
// bounding rectangle of the interfering pixels.
PixelRect classifyStencil(const raster::PixelBuffer<std::uint8_t>& stencil, PairResult& r) {
  const std::array<std::uint8_t, 256>& table = caseTable();
  r.caseMap = raster::PixelBuffer<std::uint8_t>(stencil.rect, std::uint8_t{0});
  const PixelRect& m = stencil.rect;
  // Local pointers and counts: a byte store may alias anything, so counts and pointers reached
  // through r would be reloaded after every pixel.
  const std::uint8_t* in = stencil.data.data();
  std::uint8_t* out = r.caseMap.data.data();
  std::array<long long, kCaseCount> counts{};
  int cx0 = m.x1, cy0 = m.y1, cx1 = m.x0, cy1 = m.y0;
  const auto interferesAt = [&](int x0, int x1, int y) {
    cx0 = std::min(cx0, x0);
    cy0 = std::min(cy0, y);
    cx1 = std::max(cx1, x1);
    cy1 = std::max(cy1, y + 1);
  };
  const auto decode = [&](int x, int y, std::size_t at) {
    const std::uint8_t c = table[in[at]];
    out[at] = c;
    ++counts[c];
    if (isInterfering(c))
      interferesAt(x, x + 1, y);
  };
  constexpr int kRun = 8;
  std::size_t i = 0;  // both buffers share the rectangle, so one running index serves both
  for (int y = m.y0; y < m.y1; ++y) {
    int x = m.x0;
    // Most of a MOR lies in wide regions of one case (neither block, one block alone): a run of
    // eight equal stencils is decoded once.
    for (; x + kRun <= m.x1; x += kRun, i += kRun) {
      std::uint64_t word;
      std::memcpy(&word, in + i, kRun);
      if (word != in[i] * 0x0101010101010101ULL) {
        for (int k = 0; k < kRun; ++k)
          decode(x + k, y, i + static_cast<std::size_t>(k));
        continue;
      }
      const std::uint8_t c = table[in[i]];
      std::memset(out + i, c, kRun);
      counts[c] += kRun;
      if (isInterfering(c))
        interferesAt(x, x + kRun, y);
    }
    for (; x < m.x1; ++x, ++i)
      decode(x, y, i);
  }
  addCaseCounts(counts, r);
  return r.interferingPixels > 0 ? PixelRect{cx0, cy0, cx1, cy1} : PixelRect{};
}

// The contact region from the two ends of the overlap interval over the contact rectangle.
// With `ends`, both ends of every pixel's interval are kept there, near then far.
void measureContact(const raster::PixelBuffer<std::uint32_t>& nearDepth,
                    const raster::PixelBuffer<std::uint32_t>& farDepth, const OrthoView& view,
                    PairResult& r, std::vector<Eigen::Vector3d>* ends) {
  const double depthScale = 1.0 / static_cast<double>(raster::kDepthMax);
  const double worldPerStep = (r.depthMax - r.depthMin) * depthScale;
  r.contact.points.reserve(static_cast<std::size_t>(r.interferingPixels));
  const PixelRect& rect = r.contactRect;  // the buffers may cover more (collidePairs)
  // The box, depth and count are kept in locals while the loop runs: the points' stores could
  // alias them through r and would force them through memory at every pixel.
  Aabb box = r.contact.box;
  double maxDepth = r.contact.maxDepth;
  long long collapsed = r.contact.collapsedPixels;
  // Each column's u once (toWorld's u at the pixel centre), not once per pixel.
  std::vector<double> columnU(static_cast<std::size_t>(rect.width()));
  for (int i = 0; i < rect.width(); ++i)
    columnU[static_cast<std::size_t>(i)] = view.planeU(rect.x0 + i + 0.5);
  for (int y = rect.y0; y < rect.y1; ++y) {
    const std::uint8_t* cases = &r.caseMap.at(rect.x0, y);
    const std::uint32_t* nearRow = &nearDepth.at(rect.x0, y);
    const std::uint32_t* farRow = &farDepth.at(rect.x0, y);
    const double v = view.planeV(y + 0.5);
    for (int i = 0; i < rect.width(); ++i) {
      if (!isInterfering(cases[i]))
        continue;
      std::uint32_t lo = nearRow[i], hi = farRow[i];
      // The near end can only pass the far end by rounding (the intervals touch within a
      // step at this pixel): the overlap is then taken as the single depth between them.
      if (lo > hi) {
        ++collapsed;
        lo = hi = lo / 2 + hi / 2 + (lo & hi & 1u);
      }
      // toWorld at the pixel centre for both ends, sharing their u and v.
      const double u = columnU[static_cast<std::size_t>(i)];
      const Eigen::Vector3d pn = view.fromPlane({u, v, view.planeD(lo * depthScale)});
      const Eigen::Vector3d pf = view.fromPlane({u, v, view.planeD(hi * depthScale)});
      box.extend(pn);
      box.extend(pf);
      r.contact.points.push_back(0.5 * (pn + pf));
      if (ends) {
        ends->push_back(pn);
        ends->push_back(pf);
      }
      maxDepth = std::max(maxDepth, (hi - lo) * worldPerStep);
    }
  }
  r.contact.box = box;
  r.contact.maxDepth = maxDepth;
  r.contact.collapsedPixels = collapsed;
}

// The box test on the snapped geometry the device will draw: the projected boxes must share a
// pixel centre and the depth ranges must come within one step of each other. Nothing that
// fails it can interfere, so skipping the passes then gives the verdict they would. Sets
// r.boxesOverlap and, when the passes are to run, r.mor; returns whether they are.
bool choosePassRegion(const DrawnPair& drawn, const PairRequest& request, PairResult& r) {
  const FrameSpec& frame = request.frame;
  const PixelRect footA = pixelFootprint(drawn.a.extremes(), frame.width, frame.height);
  const PixelRect footB = pixelFootprint(drawn.b.extremes(), frame.width, frame.height);
  r.boxesOverlap = !footA.intersect(footB).empty() &&
                   depthSpansMeet(depthSpan(drawn.a.extremes()), depthSpan(drawn.b.extremes()));
  if (request.boxTest && !r.boxesOverlap)
    return false;
  r.mor = chooseMor(request.mor, footA, footB, frame);
  // An empty MIN is only reachable without the box test; MAX and FULL draw even when empty.
  return !(request.mor == MorMode::Min && r.mor.empty());
}

PairResult startPair(const PairBlock& a, const PairBlock& b, const FrameSpec& frame) {
  PairResult r;
  const auto [depthMin, depthMax] = pairDepthRange(frame.axis, a.box(), b.box());
  r.depthMin = depthMin;
  r.depthMax = depthMax;
  return r;
}

OrthoView pairView(const FrameSpec& frame, const PairResult& r) {
  return OrthoView(frame.axis, frame.window, frame.width, frame.height, r.depthMin, r.depthMax);
}

void recordStencilPasses(PassRunner& passes, StepRunner& steps, const PixelRect& mor) {
  steps.run(PairStep::SetZ, [&] { passes.setZ(mor); });
  steps.run(PairStep::TestZ, [&] { passes.testZ(); });
  steps.run(PairStep::LoadAmin, [&] { passes.loadAmin(); });
  steps.run(PairStep::TestAminFront, [&] { passes.testAmin(CullMode::Back, kFrontBehindAminBit); });
  steps.run(PairStep::TestAminBack, [&] { passes.testAmin(CullMode::Front, kBackBehindAminBit); });
}

PixelRect concludeStencil(const raster::PixelBuffer<std::uint8_t>& stencil, const OrthoView& view,
                          PairResult& r) {
  const Clock::time_point t = Clock::now();
  r.stencilPixelsRead = r.mor.area();
  const PixelRect contactRect = classifyStencil(stencil, r);
  concludeVerdict(view, r);
  r.timing.classifyUs += microsecondsSince(t);
  return contactRect;
}

void concludeContact(const raster::PixelBuffer<std::uint32_t>& nearDepth,
                     const raster::PixelBuffer<std::uint32_t>& farDepth, const OrthoView& view,
                     const PairBlock& a, const PairBlock& b, const PairRequest& request,
                     PairResult& r) {
  const Clock::time_point t = Clock::now();
  r.depthPixelsRead = 2 * r.contactRect.area();
  std::vector<Eigen::Vector3d> ends;
  measureContact(nearDepth, farDepth, view, r, request.normal ? &ends : nullptr);
  if (request.normal) {
    r.contact.normal = contactNormal(OverlapSamples{ends, halfPixelExtent(view)}, a.mesh().vertices,
                                     b.mesh().vertices);
  }
  r.timing.classifyUs += microsecondsSince(t);
}

Eigen::Vector3d halfPixelExtent(const OrthoView& view) {
  return (view.fromPlane({0.5 * view.pixelWidth(), 0.5 * view.pixelHeight(), 0.0}) -
          view.fromPlane(Eigen::Vector3d::Zero()))
      .cwiseAbs();
}

const raster::StencilClasses& caseClasses() {
  static const raster::StencilClasses classes = [] {
    raster::StencilClasses c;
    c.classOf = caseTable();
    for (int k = 0; k < kCaseCount; ++k)
      if (isInterfering(k))
        c.marked = static_cast<std::uint16_t>(c.marked | (1u << k));
    return c;
  }();
  return classes;
}

PixelRect concludeSummary(const raster::PixelSummary& summary, const OrthoView& view,
                          PairResult& r) {
  const Clock::time_point t = Clock::now();
  r.stencilPixelsRead = r.mor.area();
  std::array<long long, kCaseCount> counts{};
  std::copy_n(summary.classCounts.begin(), kCaseCount, counts.begin());
  addCaseCounts(counts, r);
  concludeVerdict(view, r);
  r.timing.classifyUs += microsecondsSince(t);
  return summary.markedBounds;
}

void concludeSummaryContact(const raster::DepthIntervals& d, const OrthoView& view, PairResult& r) {
  const Clock::time_point t = Clock::now();
  const PixelRect& rect = r.contactRect;
  r.depthPixelsRead = 2 * rect.area();
  // measureContact's arithmetic at the extremes: its columns' u, rows' v and ends' depths.
  const double depthScale = 1.0 / static_cast<double>(raster::kDepthMax);
  const double worldPerStep = (r.depthMax - r.depthMin) * depthScale;
  const Eigen::Vector3d first =
      view.fromPlane({view.planeU(rect.x0 + 0.5), view.planeV(rect.y0 + 0.5),
                      view.planeD(d.nearest * depthScale)});
  const Eigen::Vector3d last =
      view.fromPlane({view.planeU((rect.x1 - 1) + 0.5), view.planeV((rect.y1 - 1) + 0.5),
                      view.planeD(d.farthest * depthScale)});
  r.contact.box.extend(first);
  r.contact.box.extend(last);
  r.contact.maxDepth = std::max(r.contact.maxDepth, d.longest * worldPerStep);
  r.contact.collapsedPixels += d.inverted;
  r.timing.classifyUs += microsecondsSince(t);
}

void dropPixelsUnlessKept(const PairRequest& request, PairResult& r) {
  if (request.keepPixels)
    return;
  // Moved from empty ones, which frees the memory (assigning {} would keep the capacity).
  r.caseMap = raster::PixelBuffer<std::uint8_t>();
  r.contact.points = std::vector<Eigen::Vector3d>();
}

}  // namespace detail

PairResult collidePair(raster::DepthStencilDevice& device, const TriangleMesh& a,
                       const TriangleMesh& b, const PairRequest& request, PairObserver* observer) {
  return collidePair(device, PairBlock(a), PairBlock(b), request, observer);
}

PairResult collidePair(raster::DepthStencilDevice& device, const PairBlock& a, const PairBlock& b,
                       const PairRequest& request, PairObserver* observer) {
  using namespace detail;
  const Clock::time_point start = Clock::now();
  const FrameSpec& frame = request.frame;
  requireDeviceSize(device, frame);
  PairResult r = startPair(a, b, frame);
  const auto finish = [&r, &request, start]() -> PairResult {
    dropPixelsUnlessKept(request, r);
    r.timing.totalUs = microsecondsSince(start);
    return std::move(r);
  };
  const OrthoView view = pairView(frame, r);
  // A before B, each whole unless it can be drawn culled, so a vertex the view cannot map is
  // refused as it always was: before anything is drawn, A's first.
  const BlockWindowSource sourceA(a, view), sourceB(b, view);
  if (!choosePassRegion(DrawnPair{sourceA, sourceB}, request, r))
    return finish();

  PassRunner passes(device, sourceA, sourceB);
  StepRunner steps(device, observer, r.timing);
  recordStencilPasses(passes, steps, r.mor);
  raster::PixelBuffer<std::uint8_t> stencil;
  steps.run(PairStep::ReadStencil, [&] { stencil = raster::readStencilBuffer(device, r.mor); });
  const PixelRect contactRect = concludeStencil(stencil, view, r);
  if (!r.collide || !request.contact)
    return finish();

  r.contactRect = contactRect;
  raster::PixelBuffer<std::uint32_t> nearDepth, farDepth;
  steps.run(PairStep::ContactNear, [&] {
    passes.overlapEnd(r.contactRect, true);
    nearDepth = raster::readDepthBuffer(device, r.contactRect);
  });
  steps.run(PairStep::ContactFar, [&] {
    passes.overlapEnd(r.contactRect, false);
    farDepth = raster::readDepthBuffer(device, r.contactRect);
  });
  concludeContact(nearDepth, farDepth, view, a, b, request, r);
  return finish();
}

}  // namespace recode::core
