#pragma once
// The pair modes above the reference (core/refine: adaptive, conservative) held against CGAL's
// exact verdict, pair by pair: what `recode verify --modes` counts and the mode tests assert.

#include <optional>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/refine/adaptive.hpp"

namespace recode::verify {

struct ModeCheck {
  bool exactIntersect = false;  // CGAL
  bool referenceCollide = false;
  core::PairVerdict adaptive = core::PairVerdict::Apart;
  int adaptiveRuns = 0;
  int adaptiveLevel = 0;
  // Reference apart, CGAL intersect, and the adaptive mode saw the contact on a finer frame.
  bool seenFiner = false;
  bool conservativeCollide = false;
  // A conservative extra (collide, CGAL apart) that CGAL confirms lies within the documented
  // bound: A grown by twice the growth (one pixel + 4/256 across, 8 steps along the view)
  // meets B. Always true when the pair is not a conservative extra.
  bool conservativeExtraWithinBound = true;
  double referenceUs = 0.0, adaptiveUs = 0.0, conservativeUs = 0.0;
};

// Runs the reference, adaptive and conservative modes on A and B in `frame` (CpuDevice) and
// compares them with `exactIntersect`, CGAL's verdict. With a conservative extra, checks its
// bound with CGAL: throws std::runtime_error when this build has no CGAL.
[[nodiscard]] ModeCheck checkModes(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                   const core::FrameSpec& frame, bool exactIntersect,
                                   core::AdaptivePairTester& tester);

struct MissExtra {
  long long found = 0, missed = 0, extra = 0;
};

struct ModeCounts {
  long long pairs = 0;
  long long truth = 0;  // pairs CGAL says intersect
  MissExtra reference, adaptive, conservative;
  long long seenFiner = 0;         // reference misses the adaptive mode saw on finer pixels
  long long apartAtLimit = 0;      // adaptive verdicts apart_at_limit (neither missed nor extra)
  long long apartAtLimitTrue = 0;  // of them, pairs CGAL says intersect
  long long conservativeExtrasBeyondBound = 0;
  long long conservativeBelowReference = 0;  // reference collide, conservative apart
  long long adaptiveRuns = 0;
  int deepestLevel = 0;
  double referenceUs = 0.0, adaptiveUs = 0.0, conservativeUs = 0.0;

  void add(const ModeCheck& check);

  // The modes' promises (docs/accuracy.md): the conservative mode misses nothing, says collide
  // wherever the reference does and keeps every extra within its bound; the adaptive mode says
  // a definite apart for no pair that intersects (its misses, apart_at_limit aside).
  [[nodiscard]] bool promisesHold() const {
    return conservative.missed == 0 && conservativeBelowReference == 0 &&
           conservativeExtrasBeyondBound == 0 && adaptive.missed == 0;
  }
};

}  // namespace recode::verify
