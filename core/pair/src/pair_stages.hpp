#pragma once
// The stages of one pair test, private to the pair layer: collidePair runs them in turn, each
// read-back waited on; collidePairs records every pair's passes first, lets the device run
// them all at once, then concludes each pair from its read-backs. Both give the same result.

#include <chrono>
#include <cstddef>

#include "recode/pair/pair.hpp"
#include "recode/raster/pixel_buffer.hpp"
#include "recode/raster/pixel_summary.hpp"

#include "block_window_source.hpp"
#include "pair_passes.hpp"

namespace recode::core::detail {

using Clock = std::chrono::steady_clock;

inline double microsecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

// Both blocks as the device will draw them.
struct DrawnPair {
  const BlockWindowSource& a;
  const BlockWindowSource& b;
};

// Runs the algorithm's steps on the device, timing each and showing it to the observer.
class StepRunner {
 public:
  StepRunner(raster::DepthStencilDevice& device, PairObserver* observer, PairTiming& timing)
      : device_(device), observer_(observer), timing_(timing) {}

  template <class Body>
  void run(PairStep step, Body&& body) {
    const Clock::time_point t = Clock::now();
    body();
    timing_.stepUs[static_cast<std::size_t>(step)] += microsecondsSince(t);
    if (observer_)
      observer_->afterStep(step, device_);
  }

 private:
  raster::DepthStencilDevice& device_;
  PairObserver* observer_;
  PairTiming& timing_;
};

// Throws std::invalid_argument unless the device is of the frame's size.
void requireDeviceSize(const raster::DepthStencilDevice& device, const FrameSpec& frame);

// A result with the pair's depth range set (pairDepthRange), and the view it gives.
[[nodiscard]] PairResult startPair(const PairBlock& a, const PairBlock& b, const FrameSpec& frame);
[[nodiscard]] OrthoView pairView(const FrameSpec& frame, const PairResult& r);

// The box test and the MOR: sets r.boxesOverlap and r.mor; returns whether the passes run.
[[nodiscard]] bool choosePassRegion(const DrawnPair& drawn, const PairRequest& request,
                                    PairResult& r);

// The five passes that leave the stencil's verdict over `mor` (SetZ to TestAminBack).
void recordStencilPasses(PassRunner& passes, StepRunner& steps, const raster::PixelRect& mor);

// The stencil over r.mor decoded: case map, counts, verdict, pixel count and area. Returns the
// bounding rectangle of the interfering pixels (empty when none).
[[nodiscard]] raster::PixelRect concludeStencil(const raster::PixelBuffer<std::uint8_t>& stencil,
                                                const OrthoView& view, PairResult& r);

// The contact region from both contact passes' depths over r.contactRect (the buffers may cover
// more: they are read at r.contactRect's pixels only), and the normal when asked for.
void concludeContact(const raster::PixelBuffer<std::uint32_t>& nearDepth,
                     const raster::PixelBuffer<std::uint32_t>& farDepth, const OrthoView& view,
                     const PairBlock& a, const PairBlock& b, const PairRequest& request,
                     PairResult& r);

// The stencil's cases as summary classes: class c is case c, the interfering cases marked.
[[nodiscard]] const raster::StencilClasses& caseClasses();

// concludeStencil from a device's summary over r.mor instead of the stencil (the case map left
// empty): the case counts, verdict, pixel count and area; returns the interfering pixels'
// bounding rectangle (the summary's marked bounds).
[[nodiscard]] raster::PixelRect concludeSummary(const raster::PixelSummary& summary,
                                                const OrthoView& view, PairResult& r);

// concludeContact from the depth intervals of a summary over r.contactRect (set) instead of the
// depths: the box, greatest depth and collapsed pixels, without points or normal. The same
// values as concludeContact's: the contact rectangle's extreme columns and rows and the
// intervals' extreme ends give the box and the greatest depth, because every world coordinate
// toWorld makes is a monotone function of one of them (docs/architecture.md).
void concludeSummaryContact(const raster::DepthIntervals& depth, const OrthoView& view,
                            PairResult& r);

// Half a pixel along the image plane's two world axes, none along the view axis: the extent a
// sample stands for in the contact normal's widths (OverlapSamples::halfPixel).
[[nodiscard]] Eigen::Vector3d halfPixelExtent(const OrthoView& view);

// Empties the case map and the contact points unless the request keeps the pixels.
void dropPixelsUnlessKept(const PairRequest& request, PairResult& r);

}  // namespace recode::core::detail
