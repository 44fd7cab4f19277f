#include "recode/pair/layered_pair.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "block_window_source.hpp"
#include "layer_passes.hpp"
#include "layer_sweep.hpp"
#include "pair_stages.hpp"

namespace recode::core {

namespace {

using detail::Clock;
using detail::DepthInterval;
using detail::Facing;
using detail::microsecondsSince;
using raster::PixelBuffer;
using raster::PixelRect;

// One facing of one mesh over the MOR: how many fragments each pixel has, and the depth of the
// k-th of them (layer k - 1, over the bounding rectangle of the pixels that have k or more).
struct FacingLayers {
  PixelBuffer<std::uint8_t> counts;
  std::vector<PixelBuffer<std::uint32_t>> depths;
};

// A mesh's fragments over the MOR, entries and exits apart.
struct MeshLayers {
  FacingLayers entries;
  FacingLayers exits;
  int layers = 0;  // the most entries at one pixel
};

// The bounding rectangle of the pixels whose count is at least k.
PixelRect pixelsWithAtLeast(const PixelBuffer<std::uint8_t>& counts, int k) {
  const PixelRect& m = counts.rect;
  int x0 = m.x1, y0 = m.y1, x1 = m.x0, y1 = m.y0;
  for (int y = m.y0; y < m.y1; ++y)
    for (int x = m.x0; x < m.x1; ++x)
      if (counts.at(x, y) >= k) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x + 1);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y + 1);
      }
  return x0 < x1 ? PixelRect{x0, y0, x1, y1} : PixelRect{};
}

// "(x, y)", written through a stream (GCC 12 warns falsely of an overlap in the equivalent
// string concatenation).
std::string pixelText(int x, int y) {
  std::ostringstream s;
  s << '(' << x << ", " << y << ')';
  return s.str();
}

// What the passes can see of a mesh that is not a closed, outward surface: a pixel whose
// entries and exits differ in number, or whose count saturated.
void requireBalancedCounts(const MeshLayers& mesh, char name) {
  const PixelRect& m = mesh.entries.counts.rect;
  for (int y = m.y0; y < m.y1; ++y)
    for (int x = m.x0; x < m.x1; ++x) {
      const int in = mesh.entries.counts.at(x, y), out = mesh.exits.counts.at(x, y);
      if (in != out) {
        std::ostringstream s;
        s << "mesh " << name << " is not closed as the view sees it: pixel " << pixelText(x, y)
          << " has " << in << " front-facing and " << out
          << " back-facing fragments (a closed, outwardly oriented mesh has as many of each at "
             "every pixel; check the mesh with the closed-mesh validation)";
        throw std::invalid_argument(s.str());
      }
      if (in > kMaxLayers) {
        std::ostringstream s;
        s << "mesh " << name << " has more than " << kMaxLayers
          << " front-facing fragments at pixel " << pixelText(x, y)
          << ": the stencil counts at most " << kMaxLayers << " layers a pixel";
        throw std::invalid_argument(s.str());
      }
    }
}

// The count passes of one mesh: entries, then exits, each read back over the MOR.
MeshLayers countLayers(detail::LayerPassRunner& passes, raster::DepthStencilDevice& device,
                       const raster::TriangleSource& mesh, const PixelRect& mor, char name) {
  MeshLayers layers;
  passes.countFragments(mesh, Facing::Entries, mor);
  layers.entries.counts = raster::readStencilBuffer(device, mor);
  passes.countFragments(mesh, Facing::Exits, mor);
  layers.exits.counts = raster::readStencilBuffer(device, mor);
  requireBalancedCounts(layers, name);
  for (const std::uint8_t c : layers.entries.counts.data)
    layers.layers = std::max(layers.layers, int{c});
  return layers;
}

// The capture passes of one facing of one mesh: layer k over the pixels that have k fragments.
// Returns the depth pixels read.
long long captureLayers(detail::LayerPassRunner& passes, raster::DepthStencilDevice& device,
                        const raster::TriangleSource& mesh, Facing facing, int layers,
                        FacingLayers& out) {
  long long read = 0;
  for (int k = 1; k <= layers; ++k) {
    const PixelRect rect = pixelsWithAtLeast(out.counts, k);
    passes.captureLayer(mesh, facing, k, rect);
    out.depths.push_back(raster::readDepthBuffer(device, rect));
    read += rect.area();
  }
  return read;
}

// One facing's depths at a pixel, sorted ascending.
void depthsAt(const FacingLayers& f, int x, int y, std::vector<std::uint32_t>& out) {
  out.clear();
  const int n = f.counts.at(x, y);
  for (int k = 0; k < n; ++k)
    out.push_back(f.depths[static_cast<std::size_t>(k)].at(x, y));
  std::sort(out.begin(), out.end());
}

// Whether the pixels whose centres lie in a mesh's window box are all in the frame (so that the
// passes see all of the mesh), from its extreme window vertices.
bool wholeInFrame(std::span<const raster::WindowVertex> extremes, const FrameSpec& frame) {
  for (const raster::WindowVertex& v : extremes)
    if (v.x < 0.0f || v.y < 0.0f || v.x > static_cast<float>(frame.width) ||
        v.y > static_cast<float>(frame.height))
      return false;
  return true;
}

// The sweep's view of one pixel, recomputed from the captured layers as Sweep::pixel computes it.
LayeredPixel probePixel(const MeshLayers& a, const MeshLayers& b, int x, int y) {
  LayeredPixel p;
  p.x = x;
  p.y = y;
  p.inMor = true;
  depthsAt(a.entries, x, y, p.entriesA);
  depthsAt(a.exits, x, y, p.exitsA);
  depthsAt(b.entries, x, y, p.entriesB);
  depthsAt(b.exits, x, y, p.exitsB);
  (void)detail::insideIntervals(p.entriesA, p.exitsA, p.insideA);
  (void)detail::insideIntervals(p.entriesB, p.exitsB, p.insideB);
  detail::intersectIntervals(p.insideA, p.insideB, p.insideBoth);
  return p;
}

bool rectWithin(const PixelRect& inner, const PixelRect& outer) {
  return !inner.empty() && outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && inner.x1 <= outer.x1 &&
         inner.y1 <= outer.y1;
}

// The sweep's running state over the MOR.
class Sweep {
 public:
  Sweep(const OrthoView& view, const PairRequest& request, LayeredPairResult& r)
      : view_(view), request_(request), r_(r) {
    const double depthScale = 1.0 / static_cast<double>(raster::kDepthMax);
    worldPerStep_ = (r.depthMax - r.depthMin) * depthScale;
    if (request.keepPixels) {
      r.overlapSteps = PixelBuffer<std::uint32_t>(r.mor, 0u);
      r.interferes = PixelBuffer<std::uint8_t>(r.mor, std::uint8_t{0});
    }
  }

  void pixel(const MeshLayers& a, const MeshLayers& b, int x, int y) {
    depthsAt(a.entries, x, y, entries_);
    depthsAt(a.exits, x, y, exits_);
    const int invertedA = detail::insideIntervals(entries_, exits_, insideA_);
    depthsAt(b.entries, x, y, entries_);
    depthsAt(b.exits, x, y, exits_);
    const int invertedB = detail::insideIntervals(entries_, exits_, insideB_);
    if (!insideA_.empty()) {
      aSeen_ = true;
      aWithinB_ = aWithinB_ && detail::liesWithin(insideA_, insideB_);
    }
    if (!insideB_.empty()) {
      bSeen_ = true;
      bWithinA_ = bWithinA_ && detail::liesWithin(insideB_, insideA_);
    }
    detail::intersectIntervals(insideA_, insideB_, both_);
    if (both_.empty())
      return;
    ++r_.interferingPixels;
    if (invertedA + invertedB > 0)
      ++r_.contact.collapsedPixels;
    contactX0_ = std::min(contactX0_, x);
    contactX1_ = std::max(contactX1_, x + 1);
    contactY0_ = std::min(contactY0_, y);
    contactY1_ = std::max(contactY1_, y + 1);
    const std::uint64_t steps = detail::totalLength(both_);
    r_.overlapVolume += static_cast<double>(steps) * worldPerStep_;  // times the area later
    if (request_.keepPixels) {
      r_.overlapSteps.at(x, y) = static_cast<std::uint32_t>(steps);
      r_.interferes.at(x, y) = 1;
    }
    if (request_.contact)
      addContact(x, y);
  }

  void finish(bool aMayBeInside, bool bMayBeInside) {
    const double pixelArea = view_.pixelWidth() * view_.pixelHeight();
    r_.overlapVolume *= pixelArea;
    r_.collide = r_.interferingPixels > 0;
    r_.contact.pixels = r_.interferingPixels;
    r_.contact.area = static_cast<double>(r_.interferingPixels) * pixelArea;
    if (r_.collide)
      r_.contactRect = {contactX0_, contactY0_, contactX1_, contactY1_};
    const bool aInside = aMayBeInside && aSeen_ && aWithinB_;
    const bool bInside = bMayBeInside && bSeen_ && bWithinA_;
    r_.containment = aInside && bInside ? Containment::Same
                     : aInside          ? Containment::AInsideB
                     : bInside          ? Containment::BInsideA
                                        : Containment::None;
  }

  std::vector<Eigen::Vector3d> ends;  // both ends of every overlap interval, for the normal

 private:
  void addContact(int x, int y) {
    const double depthScale = 1.0 / static_cast<double>(raster::kDepthMax);
    const double u = view_.planeU(x + 0.5), v = view_.planeV(y + 0.5);
    for (const DepthInterval& d : both_) {
      const Eigen::Vector3d pn = view_.fromPlane({u, v, view_.planeD(d.min * depthScale)});
      const Eigen::Vector3d pf = view_.fromPlane({u, v, view_.planeD(d.max * depthScale)});
      r_.contact.box.extend(pn);
      r_.contact.box.extend(pf);
      r_.contact.points.push_back(0.5 * (pn + pf));
      r_.contact.maxDepth = std::max(r_.contact.maxDepth, (d.max - d.min) * worldPerStep_);
      if (request_.normal) {
        ends.push_back(pn);
        ends.push_back(pf);
      }
    }
  }

  const OrthoView& view_;
  const PairRequest& request_;
  LayeredPairResult& r_;
  double worldPerStep_ = 0.0;
  std::vector<std::uint32_t> entries_, exits_;
  std::vector<DepthInterval> insideA_, insideB_, both_;
  bool aSeen_ = false, bSeen_ = false, aWithinB_ = true, bWithinA_ = true;
  int contactX0_ = 1 << 30, contactY0_ = 1 << 30, contactX1_ = -(1 << 30), contactY1_ = -(1 << 30);
};

}  // namespace

std::string_view toString(LayerStep step) {
  switch (step) {
    case LayerStep::Count:
      return "count";
    case LayerStep::Capture:
      return "capture";
    case LayerStep::Sweep:
      return "sweep";
  }
  return "?";
}

std::string_view toString(Containment c) {
  switch (c) {
    case Containment::None:
      return "none";
    case Containment::AInsideB:
      return "a_inside_b";
    case Containment::BInsideA:
      return "b_inside_a";
    case Containment::Same:
      return "same";
  }
  return "?";
}

LayeredPairResult collideLayered(raster::DepthStencilDevice& device, const TriangleMesh& a,
                                 const TriangleMesh& b, const PairRequest& request) {
  return collideLayered(device, PairBlock(a), PairBlock(b), request);
}

namespace {

// collideLayered, with result.pixel for `probe` when it is not null.
LayeredPairResult collideLayeredProbing(raster::DepthStencilDevice& device, const PairBlock& a,
                                        const PairBlock& b, const PairRequest& request,
                                        const std::array<int, 2>* probe);

}  // namespace

LayeredPairResult collideLayered(raster::DepthStencilDevice& device, const PairBlock& a,
                                 const PairBlock& b, const PairRequest& request) {
  return collideLayeredProbing(device, a, b, request, nullptr);
}

LayeredPairResult collideLayered(raster::DepthStencilDevice& device, const PairBlock& a,
                                 const PairBlock& b, const PairRequest& request,
                                 std::array<int, 2> probe) {
  return collideLayeredProbing(device, a, b, request, &probe);
}

namespace {

LayeredPairResult collideLayeredProbing(raster::DepthStencilDevice& device, const PairBlock& a,
                                        const PairBlock& b, const PairRequest& request,
                                        const std::array<int, 2>* probe) {
  using namespace detail;
  const Clock::time_point start = Clock::now();
  const FrameSpec& frame = request.frame;
  requireDeviceSize(device, frame);
  // The frame, the view, the box test and the MOR are collidePair's.
  PairResult region = startPair(a, b, frame);
  LayeredPairResult r;
  if (probe) {
    r.pixel.emplace();
    r.pixel->x = (*probe)[0];
    r.pixel->y = (*probe)[1];
  }
  r.depthMin = region.depthMin;
  r.depthMax = region.depthMax;
  const auto finish = [&r, start]() -> LayeredPairResult {
    r.timing.totalUs = microsecondsSince(start);
    return std::move(r);
  };
  const OrthoView view = pairView(frame, region);
  const BlockWindowSource sourceA(a, view), sourceB(b, view);
  const bool draws = choosePassRegion(DrawnPair{sourceA, sourceB}, request, region);
  r.boxesOverlap = region.boxesOverlap;
  if (!draws)
    return finish();
  r.mor = region.mor;

  LayerPassRunner passes(device);
  const auto timed = [&r](LayerStep step, auto&& body) {
    const Clock::time_point t = Clock::now();
    body();
    r.timing.stepUs[static_cast<std::size_t>(step)] += microsecondsSince(t);
  };
  MeshLayers layersA, layersB;
  timed(LayerStep::Count, [&] {
    layersA = countLayers(passes, device, sourceA, r.mor, 'A');
    layersB = countLayers(passes, device, sourceB, r.mor, 'B');
  });
  r.layersA = layersA.layers;
  r.layersB = layersB.layers;
  r.stencilPixelsRead = 4 * r.mor.area();
  timed(LayerStep::Capture, [&] {
    for (auto [mesh, layers] : {std::pair{&sourceA, &layersA}, std::pair{&sourceB, &layersB}}) {
      r.depthPixelsRead +=
          captureLayers(passes, device, *mesh, Facing::Entries, layers->layers, layers->entries);
      r.depthPixelsRead +=
          captureLayers(passes, device, *mesh, Facing::Exits, layers->layers, layers->exits);
    }
  });
  r.passes = 4 + 2 * (r.layersA + r.layersB);

  timed(LayerStep::Sweep, [&] {
    Sweep sweep(view, request, r);
    for (int y = r.mor.y0; y < r.mor.y1; ++y)
      for (int x = r.mor.x0; x < r.mor.x1; ++x)
        sweep.pixel(layersA, layersB, x, y);
    if (probe && r.mor.x0 <= (*probe)[0] && (*probe)[0] < r.mor.x1 && r.mor.y0 <= (*probe)[1] &&
        (*probe)[1] < r.mor.y1)
      r.pixel = probePixel(layersA, layersB, (*probe)[0], (*probe)[1]);
    // A mesh lies inside the other only if the passes saw all of it: its footprint inside the
    // other's (so inside the MOR) and inside the frame.
    const PixelRect footA = pixelFootprint(sourceA.extremes(), frame.width, frame.height);
    const PixelRect footB = pixelFootprint(sourceB.extremes(), frame.width, frame.height);
    sweep.finish(rectWithin(footA, footB) && wholeInFrame(sourceA.extremes(), frame),
                 rectWithin(footB, footA) && wholeInFrame(sourceB.extremes(), frame));
    if (request.normal && r.collide && request.contact)
      r.contact.normal = contactNormal(OverlapSamples{sweep.ends, halfPixelExtent(view)},
                                       a.mesh().vertices, b.mesh().vertices);
  });
  return finish();
}

}  // namespace

}  // namespace recode::core
