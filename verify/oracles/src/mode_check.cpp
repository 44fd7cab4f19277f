#include "recode/verify/mode_check.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/state.hpp"
#include "recode/verify/cgal_oracle.hpp"

namespace recode::verify {

namespace {

using Clock = std::chrono::steady_clock;

double microsecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

// The bound a conservative extra must keep: the grown blocks meet only if A and B differ by a
// vector of S - S (twice the growth), and the device may report grown blocks that only come
// within its rounding of each other (kEdgeTolerancePixels across, kDepthToleranceLsb depth
// steps of the grown pair's range along the view). Only the CGAL check uses it.
#if RECODE_HAVE_CGAL
Eigen::Vector3d extraBound(const core::FrameSpec& frame, const core::ConservativeResult& r) {
  Eigen::Vector3d bound = 2.0 * r.growth;
  const int d = static_cast<int>(frame.axis);
  const int u = (d + 1) % 3, v = (d + 2) % 3;
  bound[u] += kEdgeTolerancePixels * (frame.window.umax - frame.window.umin) / frame.width;
  bound[v] += kEdgeTolerancePixels * (frame.window.vmax - frame.window.vmin) / frame.height;
  bound[d] += kDepthToleranceLsb * (r.pair.depthMax - r.pair.depthMin) /
              static_cast<double>(raster::kDepthMax);
  return bound;
}
#endif

void score(MissExtra& m, bool found, bool truth) {
  m.found += found ? 1 : 0;
  m.missed += truth && !found ? 1 : 0;
  m.extra += found && !truth ? 1 : 0;
}

}  // namespace

ModeCheck checkModes(const core::TriangleMesh& a, const core::TriangleMesh& b,
                     const core::FrameSpec& frame, bool exactIntersect,
                     core::AdaptivePairTester& tester) {
  raster::CpuDevice device(frame.width, frame.height);
  core::PairRequest request;
  request.frame = frame;
  ModeCheck c;
  c.exactIntersect = exactIntersect;
  Clock::time_point t = Clock::now();
  c.referenceCollide = core::collidePair(device, a, b, request).collide;
  c.referenceUs = microsecondsSince(t);
  t = Clock::now();
  const core::AdaptiveResult adaptive = tester.collide(device, a, b, request);
  c.adaptiveUs = microsecondsSince(t);
  c.adaptive = adaptive.verdict;
  c.adaptiveRuns = adaptive.runs;
  c.adaptiveLevel = adaptive.deepestLevel;
  c.seenFiner = exactIntersect && !c.referenceCollide &&
                adaptive.verdict == core::PairVerdict::Collide && adaptive.deepestLevel > 0;
  t = Clock::now();
  const core::ConservativeResult conservative = core::collideConservative(device, a, b, request);
  c.conservativeUs = microsecondsSince(t);
  c.conservativeCollide = conservative.pair.collide;
  if (c.conservativeCollide && !exactIntersect) {
#if RECODE_HAVE_CGAL
    c.conservativeExtraWithinBound = grownBlockMeets(a, extraBound(frame, conservative), b);
#else
    throw std::runtime_error(
        "checking a conservative extra's bound needs the CGAL oracle (RECODE_WITH_CGAL)");
#endif
  }
  return c;
}

void ModeCounts::add(const ModeCheck& c) {
  ++pairs;
  truth += c.exactIntersect ? 1 : 0;
  score(reference, c.referenceCollide, c.exactIntersect);
  if (c.adaptive == core::PairVerdict::ApartAtLimit) {
    ++apartAtLimit;
    apartAtLimitTrue += c.exactIntersect ? 1 : 0;
  } else {
    score(adaptive, c.adaptive == core::PairVerdict::Collide, c.exactIntersect);
  }
  score(conservative, c.conservativeCollide, c.exactIntersect);
  seenFiner += c.seenFiner ? 1 : 0;
  conservativeExtrasBeyondBound += c.conservativeExtraWithinBound ? 0 : 1;
  conservativeBelowReference += c.referenceCollide && !c.conservativeCollide ? 1 : 0;
  adaptiveRuns += c.adaptiveRuns;
  deepestLevel = std::max(deepestLevel, c.adaptiveLevel);
  referenceUs += c.referenceUs;
  adaptiveUs += c.adaptiveUs;
  conservativeUs += c.conservativeUs;
}

}  // namespace recode::verify
