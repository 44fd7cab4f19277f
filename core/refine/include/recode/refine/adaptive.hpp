#pragma once
// Modes above the pair algorithm (docs/algorithm.md, "Beyond the paper"). Both call
// core::collidePair unchanged, on other blocks or in other frames:
//
// - conservative: both blocks grown by a box of half a pixel (plus 2/256 px) across and four
//   depth steps along the view. If the blocks meet, some pixel centre's whole +-1/256 px
//   square lies over a common box of both grown blocks with an overlap of 8 steps, which the
//   device must see: it never misses. It may report blocks up to one pixel (+1/128) apart
//   along each image axis and 8 depth steps along the view.
// - adaptive: where the conservative run sees a possible contact but the reference run none
//   (or only a touch within depth rounding), the blocks are clipped to the small region the
//   conservative contact spans and the pair is run again on frames with pixels `factor` times
//   smaller, tile by tile, recursively, until the contact is seen, ruled out, or the limit is
//   reached (apart_at_limit). In the request's frame the reference run comes first; then
//   blocks that GJK's certified gap (convexHullGap) proves apart are apart, whatever that run
//   saw, and without any refinement; otherwise a deep contact there is the answer.

#include <memory>
#include <optional>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/raster/device.hpp"
#include "recode/refine/pair_mode.hpp"

namespace recode::core {

// Depth steps the conservative growth adds along the view on each side.
inline constexpr double kConservativeDepthSteps = 4.0;

// The conservative growth for a pair in `frame`: half-sides in world x, y, z. Across the view,
// half a pixel plus 2/256 of a pixel; along it, kConservativeDepthSteps steps of the grown
// pair's depth range (so the steps are those collidePair will use on the grown blocks).
[[nodiscard]] Eigen::Vector3d conservativeGrowth(const FrameSpec& frame, const Aabb& a,
                                                 const Aabb& b);

struct ConservativeResult {
  PairResult pair;         // collidePair of the grown blocks (its contact region is theirs)
  Eigen::Vector3d growth;  // the half-sides each block was grown by, world x, y, z
};

// RECODE on both blocks grown by conservativeGrowth(request.frame, ...).
[[nodiscard]] ConservativeResult collideConservative(raster::DepthStencilDevice& device,
                                                     const TriangleMesh& a, const TriangleMesh& b,
                                                     const PairRequest& request);

struct RefineLimits {
  int maxLevel = 6;       // refinements below the request's frame
  int factor = 4;         // each level's pixels are this many times smaller per axis
  int tileSide = 64;      // refined frames are tileSide x tileSide pixels; larger regions tiled
  int maxRuns = 96;       // collidePair calls per query, all levels together
  double touchSteps = 3;  // a reference contact no deeper than this many depth steps is only a
                          // touch within rounding, and is refined like a miss
};

struct AdaptiveResult {
  PairVerdict verdict = PairVerdict::Apart;
  // The reference run in the request's frame, when it ran (the conservative run rules most
  // separated pairs out first, and then it does not).
  std::optional<PairResult> reference;
  // The run that saw the contact (the reference one, or a refined one) and its frame.
  std::optional<PairResult> contact;
  FrameSpec contactFrame;
  int contactLevel = 0;    // the level of contactFrame (0: the request's frame)
  int deepestLevel = 0;    // 0: decided in the request's frame
  int runs = 0;            // collidePair calls
  double finestPixel = 0;  // the larger side of the smallest pixel drawn, world units
  Aabb unresolved;         // apart_at_limit: the region a contact could not be ruled out in
};

// Runs the adaptive mode; keeps the device its refined frames are drawn on. One tester is
// used by one thread at a time.
class AdaptivePairTester {
 public:
  explicit AdaptivePairTester(RefineLimits limits = {});
  ~AdaptivePairTester();
  AdaptivePairTester(const AdaptivePairTester&) = delete;
  AdaptivePairTester& operator=(const AdaptivePairTester&) = delete;

  // `device` is the request frame's (as collidePair's); refined frames use the tester's own.
  // Throws what collidePair throws for the request's frame.
  [[nodiscard]] AdaptiveResult collide(raster::DepthStencilDevice& device, const TriangleMesh& a,
                                       const TriangleMesh& b, const PairRequest& request);
  // The same, with the reference run in the request's frame drawn from blocks that may carry
  // triangle hierarchies (collidePair's culled draws, as the reference mode draws them).
  [[nodiscard]] AdaptiveResult collide(raster::DepthStencilDevice& device, const PairBlock& a,
                                       const PairBlock& b, const PairRequest& request);

  [[nodiscard]] const RefineLimits& limits() const { return limits_; }

 private:
  struct Search;
  RefineLimits limits_;
  std::unique_ptr<raster::DepthStencilDevice> tileDevice_;
};

}  // namespace recode::core
