#pragma once
// The Embree per-pixel interval oracle (docs/verification.md "Embree"): an
// independent measurement of each block's depth interval at every pixel centre, by ray casts
// along the view axis through the same snapped window-space geometry the device draws, with
// the depth of the hit triangle re-evaluated in double. It checks a PairResult's case map
// pixel by pixel and explains every disagreement as a depth tie or an edge sample, or counts
// it as unexplained. Embree itself stays in the implementation: nothing here names it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/raster/state.hpp"

namespace recode::verify {

// How far, in 24-bit depth steps, the device's depth of a block's boundary may lie from the
// oracle's at a pixel whose centre is at least 1/256 px from every projected edge. The device
// interpolates the vertices' single-precision depths; the oracle interpolates the unrounded
// ones. Each vertex depth is off by at most half a float ulp (at most half a step for depths
// below 1), an interpolated depth inside the triangle by no more, and both sides then round to
// the nearest step, so the two quantised depths differ by at most one step.
// docs/verification.md gives the measurements that hold it.
inline constexpr std::uint32_t kEmbreeDepthTolerance = 1;

enum class DisagreementKind {
  Edge,         // the pixel centre is within 1/256 px of a projected edge of either block
  Tie,          // the device's case follows from the oracle's ends moved by the tolerance
  Unexplained,  // neither: a bug in the device, the algorithm or the oracle
};
[[nodiscard]] std::string_view toString(DisagreementKind kind);

// A pixel whose case the device and the oracle disagree on.
struct PixelDisagreement {
  int x = 0;
  int y = 0;
  // The device's case, or kOutsideMor for a pixel outside the MOR (or in a pair whose
  // passes were skipped), where the device's answer is "not interfering".
  int deviceCase = 0;
  int oracleCase = 0;
  DisagreementKind kind = DisagreementKind::Unexplained;
  std::optional<core::DepthInterval> a;  // the oracle's quantised intervals (nullopt: absent)
  std::optional<core::DepthInterval> b;
};
inline constexpr int kOutsideMor = -1;

struct EmbreeCounts {
  long long pixels = 0;  // pixels examined; always agree + ties + edges + unexplained
  long long agree = 0;
  long long ties = 0;
  long long edges = 0;
  long long unexplained = 0;

  // Inline so that totals can be kept in builds without Embree.
  EmbreeCounts& operator+=(const EmbreeCounts& o) {
    pixels += o.pixels;
    agree += o.agree;
    ties += o.ties;
    edges += o.edges;
    unexplained += o.unexplained;
    return *this;
  }
};

struct EmbreeReport {
  EmbreeCounts counts;
  // The first kMaxListedDisagreements unexplained pixels, bottom row first, for messages.
  std::vector<PixelDisagreement> unexplained;
  long long rays = 0;
  // Pixels whose Embree hits could not be trusted (a hit on a face of the wrong facing or
  // of zero projected area, entry behind exit): their intervals came from testing every
  // triangle of the block instead. Reported to show how rarely float ray casting needs help.
  long long fallbackPixels = 0;
};
inline constexpr std::size_t kMaxListedDisagreements = 16;

// The oracle's view of a pixel rectangle, row-major from the bottom row up.
struct EmbreeSamples {
  raster::PixelRect rect;
  std::vector<std::optional<core::DepthInterval>> a;
  std::vector<std::optional<core::DepthInterval>> b;
  std::vector<std::uint8_t> cases;  // core::caseFromIntervals(a, b)
  // 1 where the pixel centre lies within 1/256 px of a projected edge of either block.
  std::vector<std::uint8_t> nearEdge;
  long long rays = 0;
  long long fallbackPixels = 0;
};

// One Embree device, reused for every pair this object checks. Not thread-safe: use one
// oracle per thread. Throws std::runtime_error if Embree cannot start.
class EmbreeOracle {
 public:
  EmbreeOracle();
  ~EmbreeOracle();
  EmbreeOracle(EmbreeOracle&&) noexcept;
  EmbreeOracle& operator=(EmbreeOracle&&) noexcept;
  EmbreeOracle(const EmbreeOracle&) = delete;
  EmbreeOracle& operator=(const EmbreeOracle&) = delete;

  // Checks result (core::collidePair of worldA, worldB in frame) pixel by pixel over the MOR
  // and, outside it, over every pixel whose centre lies in both blocks' window footprints.
  // Throws std::invalid_argument when result cannot belong to this pair and frame (its depth
  // range, MOR or case map do not fit) or the view cannot map the blocks.
  [[nodiscard]] EmbreeReport check(const core::FrameSpec& frame, const core::TriangleMesh& worldA,
                                   const core::TriangleMesh& worldB,
                                   const core::PairResult& result);

  // The oracle's intervals, cases and edge flags over `rect` (clamped to the frame), the
  // depth mapped over core::pairDepthRange of both blocks as collidePair maps it.
  [[nodiscard]] EmbreeSamples sample(const core::FrameSpec& frame, const core::TriangleMesh& worldA,
                                     const core::TriangleMesh& worldB,
                                     const raster::PixelRect& rect);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-off check with an oracle of its own (starting an Embree device each call).
[[nodiscard]] EmbreeReport checkCasesWithEmbree(const core::FrameSpec& frame,
                                                const core::TriangleMesh& worldA,
                                                const core::TriangleMesh& worldB,
                                                const core::PairResult& result);

// Whether deviceCase (0-8, or kOutsideMor meaning any non-interfering case) follows from the
// intervals a and b with each of their four ends moved by at most `tolerance` steps (every
// combination is tried; a block's presence is never changed).
[[nodiscard]] bool caseWithinTolerance(const std::optional<core::DepthInterval>& a,
                                       const std::optional<core::DepthInterval>& b, int deviceCase,
                                       std::uint32_t tolerance);

}  // namespace recode::verify
