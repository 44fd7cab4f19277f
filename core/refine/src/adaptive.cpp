#include "recode/refine/adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "recode/geometry/convex_distance.hpp"
#include "recode/geometry/obb.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/state.hpp"
#include "recode/refine/block_clip.hpp"
#include "recode/refine/block_growth.hpp"

namespace recode::core {

namespace {

// World axes of the image plane's u and v and of the view direction.
struct PlaneAxes {
  int u, v, d;
};

PlaneAxes planeAxes(ViewAxis axis) {
  switch (axis) {
    case ViewAxis::X:
      return {1, 2, 0};
    case ViewAxis::Y:
      return {2, 0, 1};
    case ViewAxis::Z:
      break;
  }
  return {0, 1, 2};
}

double pixelU(const FrameSpec& f) {
  return (f.window.umax - f.window.umin) / f.width;
}
double pixelV(const FrameSpec& f) {
  return (f.window.vmax - f.window.vmin) / f.height;
}

Aabb intersection(const Aabb& a, const Aabb& b) {
  Aabb r;
  r.min = a.min.cwiseMax(b.min);
  r.max = a.max.cwiseMin(b.max);
  return r;
}

Aabb grown(Aabb box, const Eigen::Vector3d& by) {
  box.min -= by;
  box.max += by;
  return box;
}

// The smallest growth along the view, relative to the coordinates' magnitude: hundreds of
// ulps, so that grown and clipped geometry is never lost to double rounding.
constexpr double kGrowthRoundingFloor = 1e-13;

}  // namespace

Eigen::Vector3d conservativeGrowth(const FrameSpec& frame, const Aabb& a, const Aabb& b) {
  const PlaneAxes ax = planeAxes(frame.axis);
  constexpr double kAcross = 0.5 + 2.0 / 256.0;
  Eigen::Vector3d half;
  half[ax.u] = kAcross * pixelU(frame);
  half[ax.v] = kAcross * pixelV(frame);
  // The grown pair's range is range + 2e and e must be k of its steps: e = k range / (N - 2k).
  const double range = std::max(a.max[ax.d], b.max[ax.d]) - std::min(a.min[ax.d], b.min[ax.d]);
  const double n = static_cast<double>(raster::kDepthMax);
  half[ax.d] = kConservativeDepthSteps * range / (n - 2.0 * kConservativeDepthSteps);
  // Deep in a refinement the range can be so short that four of its steps are below the
  // rounding of the coordinates themselves; the growth never goes below that rounding.
  const double scale = std::max(
      {std::abs(a.min[ax.d]), std::abs(a.max[ax.d]), std::abs(b.min[ax.d]), std::abs(b.max[ax.d])});
  half[ax.d] = std::max(half[ax.d], kGrowthRoundingFloor * scale);
  return half;
}

ConservativeResult collideConservative(raster::DepthStencilDevice& device, const TriangleMesh& a,
                                       const TriangleMesh& b, const PairRequest& request) {
  ConservativeResult out;
  out.growth = conservativeGrowth(request.frame, boundingBox(a), boundingBox(b));
  out.pair = collidePair(device, grownByBox(a, out.growth), grownByBox(b, out.growth), request);
  return out;
}

struct AdaptivePairTester::Search {
  const RefineLimits& limits;
  raster::DepthStencilDevice& tileDevice;
  AdaptiveResult& out;
  const TriangleMesh& wholeA;  // the blocks as given: grown, then clipped, at every level
  const TriangleMesh& wholeB;
  bool hitLimit = false;

  // The conservative run for the pieces of A and B in `tile` (nullopt: the whole blocks). The
  // whole blocks are grown and then clipped to the tile grown alike: that holds every point of
  // the grown pieces (a superset: still never misses), and the growth only ever sweeps the
  // valid blocks as given, never a clipped piece with its slivers.
  ConservativeResult conservative(raster::DepthStencilDevice& device, const TriangleMesh& a,
                                  const TriangleMesh& b, const std::optional<Aabb>& tile,
                                  const PairRequest& request) const {
    if (!tile)
      return collideConservative(device, a, b, request);
    // Steps of the range the grown pieces can span: the tile's along the view.
    Aabb span = boundingBox(a);
    span.extend(boundingBox(b));
    const PlaneAxes ax = planeAxes(request.frame.axis);
    span.min[ax.d] = std::min(span.min[ax.d], tile->min[ax.d]);
    span.max[ax.d] = std::max(span.max[ax.d], tile->max[ax.d]);
    ConservativeResult r;
    r.growth = conservativeGrowth(request.frame, span, span);
    const Aabb grownTile = grown(*tile, r.growth);
    const TriangleMesh ga = clippedToBox(grownByBox(wholeA, r.growth), grownTile);
    const TriangleMesh gb = clippedToBox(grownByBox(wholeB, r.growth), grownTile);
    if (ga.triangles.empty() || gb.triangles.empty())
      return r;  // nothing of one grown block near the tile: apart there
    r.pair = collidePair(device, ga, gb, request);
    return r;
  }

  PairRequest requestFor(const FrameSpec& frame) const {
    PairRequest r;
    r.frame = frame;
    r.mor = MorMode::Min;
    r.contact = true;
    return r;
  }

  void noteFrame(const FrameSpec& frame, int level) {
    const double p = std::max(pixelU(frame), pixelV(frame));
    out.finestPixel = out.runs == 0 ? p : std::min(out.finestPixel, p);
    out.deepestLevel = std::max(out.deepestLevel, level);
  }

  // A contact deeper than a touch within depth rounding.
  bool deep(const PairResult& ref) const {
    const double step = (ref.depthMax - ref.depthMin) / static_cast<double>(raster::kDepthMax);
    return ref.collide && ref.contact.maxDepth > limits.touchSteps * step;
  }

  // The request's frame: the reference run first, as the reference mode draws it. Then GJK's
  // certified gap (convexHullGap): blocks with a gap above rounding are apart, exactly,
  // whatever the pixels saw (a contact the reference run reports across such a gap is a touch
  // within depth rounding; no finer frame could see them meet), so nothing more is drawn.
  // Otherwise the blocks touch or intersect: a deep contact is the answer (refine() would find
  // it after the conservative run, which sees every contact the reference run sees), and the
  // rest are refined until a finer frame sees the contact.
  bool top(raster::DepthStencilDevice& device, const PairBlock& a, const PairBlock& b,
           const FrameSpec& frame) {
    noteFrame(frame, 0);
    ++out.runs;
    PairResult ref = collidePair(device, a, b, requestFor(frame));
    out.reference = ref;
    if (convexHullGap(a.mesh().vertices, b.mesh().vertices) > 0.0)
      return false;
    if (deep(ref) || (ref.collide && limits.maxLevel == 0)) {
      out.contact = std::move(ref);
      out.contactFrame = frame;
      return true;
    }
    return refine(device, a.mesh(), b.mesh(), std::nullopt, frame, 0, std::move(ref));
  }

  // True when a contact was seen in this frame or below it. `given` is the reference run in
  // this frame when it was made already.
  bool refine(raster::DepthStencilDevice& device, const TriangleMesh& a, const TriangleMesh& b,
              const std::optional<Aabb>& tileBox, const FrameSpec& frame, int level,
              std::optional<PairResult> given = std::nullopt) {
    if (!given)
      noteFrame(frame, level);
    const PairRequest request = requestFor(frame);
    ++out.runs;
    const ConservativeResult wide = conservative(device, a, b, tileBox, request);
    if (!wide.pair.collide)
      return false;  // not even within a pixel: no finer grid can see a contact here
    if (!given)
      ++out.runs;
    PairResult ref = given ? std::move(*given) : collidePair(device, a, b, request);
    const bool last = level >= limits.maxLevel || out.runs + 2 > limits.maxRuns;
    if (deep(ref) || (ref.collide && last)) {
      out.contact = std::move(ref);
      out.contactFrame = frame;
      out.contactLevel = level;
      return true;
    }
    const Aabb region = possibleContactRegion(a, b, wide);
    if (region.isEmpty())
      return false;
    if (last) {
      hitLimit = true;
      out.unresolved.extend(region);
      return false;
    }
    return refineTiles(a, b, region, frame, level);
  }

  // Every common point of A and B lies within one growth of the grown blocks' contact box (the
  // pixel that must see it is within half a pixel across, its overlap interval holds the
  // point's depth) and in both boxes: the region a finer grid must look at.
  static Aabb possibleContactRegion(const TriangleMesh& a, const TriangleMesh& b,
                                    const ConservativeResult& wide) {
    const Eigen::Vector3d margin = 2.0 * wide.growth;
    return intersection(grown(wide.pair.contact.box, margin),
                        intersection(grown(boundingBox(a), margin), grown(boundingBox(b), margin)));
  }

  // The tiles of `region` at the next level: tileSide x tileSide pixels, `factor` times smaller
  // per axis than the frame's, row by row from the region's lower corner; the last row and
  // column are cut at the region's edge. nu x nv of them.
  struct Tiling {
    PlaneAxes ax;
    double u0, v0, tileU, tileV;
    int nu, nv;

    [[nodiscard]] Aabb tile(const Aabb& region, int i, int j) const {
      Aabb t = region;
      t.min[ax.u] = u0 + i * tileU;
      t.max[ax.u] = std::min(region.max[ax.u], u0 + (i + 1) * tileU);
      t.min[ax.v] = v0 + j * tileV;
      t.max[ax.v] = std::min(region.max[ax.v], v0 + (j + 1) * tileV);
      return t;
    }
    // The tile's frame: the whole tile side in pixels, from the tile's lower corner.
    [[nodiscard]] FrameSpec frame(ViewAxis axis, int side, const Aabb& t) const {
      FrameSpec sub;
      sub.axis = axis;
      sub.width = side;
      sub.height = side;
      sub.window = {t.min[ax.u], t.min[ax.v], t.min[ax.u] + tileU, t.min[ax.v] + tileV};
      return sub;
    }
  };

  [[nodiscard]] Tiling tiling(const Aabb& region, const FrameSpec& frame) const {
    Tiling t;
    t.ax = planeAxes(frame.axis);
    const double pu = pixelU(frame) / limits.factor, pv = pixelV(frame) / limits.factor;
    t.tileU = limits.tileSide * pu;
    t.tileV = limits.tileSide * pv;
    t.u0 = region.min[t.ax.u];
    t.v0 = region.min[t.ax.v];
    t.nu = std::max(1, static_cast<int>(std::ceil((region.max[t.ax.u] - t.u0) / t.tileU)));
    t.nv = std::max(1, static_cast<int>(std::ceil((region.max[t.ax.v] - t.v0) / t.tileV)));
    return t;
  }

  // Refines each tile of `region` holding pieces of both blocks, until one sees a contact (true)
  // or the run limit leaves the region unresolved.
  bool refineTiles(const TriangleMesh& a, const TriangleMesh& b, const Aabb& region,
                   const FrameSpec& frame, int level) {
    const Tiling tiles = tiling(region, frame);
    for (int j = 0; j < tiles.nv; ++j) {
      for (int i = 0; i < tiles.nu; ++i) {
        if (out.runs + 2 > limits.maxRuns) {
          hitLimit = true;
          out.unresolved.extend(region);
          return false;
        }
        const Aabb tile = tiles.tile(region, i, j);
        const TriangleMesh ca = clippedToBox(a, tile);
        if (ca.triangles.empty())
          continue;
        const TriangleMesh cb = clippedToBox(b, tile);
        if (cb.triangles.empty())
          continue;
        try {
          if (refine(tileDevice, ca, cb, tile, tiles.frame(frame.axis, limits.tileSide, tile),
                     level + 1))
            return true;
        } catch (const std::invalid_argument&) {
          // A clipped piece the view cannot map (both flat in one depth plane): unresolved.
          hitLimit = true;
          out.unresolved.extend(tile);
        }
      }
    }
    return false;
  }
};

AdaptivePairTester::AdaptivePairTester(RefineLimits limits) : limits_(limits) {
  if (limits_.maxLevel < 0 || limits_.factor < 2 || limits_.tileSide < 1 ||
      limits_.tileSide > raster::kMaxFramebufferSize || limits_.maxRuns < 2 ||
      !(limits_.touchSteps >= 0.0))
    throw std::invalid_argument(
        "refine limits: maxLevel >= 0, factor >= 2, 1 <= tileSide <= 16384, maxRuns >= 2 and "
        "touchSteps >= 0 are required");
  tileDevice_ = std::make_unique<raster::CpuDevice>(limits_.tileSide, limits_.tileSide);
}

AdaptivePairTester::~AdaptivePairTester() = default;

AdaptiveResult AdaptivePairTester::collide(raster::DepthStencilDevice& device,
                                           const TriangleMesh& a, const TriangleMesh& b,
                                           const PairRequest& request) {
  return collide(device, PairBlock(a), PairBlock(b), request);
}

AdaptiveResult AdaptivePairTester::collide(raster::DepthStencilDevice& device, const PairBlock& a,
                                           const PairBlock& b, const PairRequest& request) {
  AdaptiveResult out;
  out.contactFrame = request.frame;
  // Boxes apart (closed): exactly apart, nothing to draw.
  if (!aabbsOverlap(a.box(), b.box()))
    return out;
  Search search{limits_, *tileDevice_, out, a.mesh(), b.mesh()};
  if (search.top(device, a, b, request.frame)) {
    out.verdict = PairVerdict::Collide;
    return out;
  }
  // Unresolved: keep what the request's frame saw (a touch within rounding stays a contact).
  if (search.hitLimit)
    out.verdict =
        out.reference && out.reference->collide ? PairVerdict::Collide : PairVerdict::ApartAtLimit;
  return out;
}

}  // namespace recode::core
