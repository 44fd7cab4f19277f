#pragma once
// Scoring a detector's answers against the exact judge's, frame by frame (`recode bench`):
// a pair the judge says collides and the detector does not report is missed; a pair the
// detector reports and the judge says is apart is extra. So on every judged frame
//   found - extra + missed == truth.

#include <vector>

#include "recode/verify/scene_detector.hpp"

namespace recode::verify {

struct DetectionScore {
  long long truth = 0;   // pairs the exact judge says collide
  long long found = 0;   // pairs the detector reports
  long long missed = 0;  // in truth, not found
  long long extra = 0;   // found, not in truth
  DetectionScore& operator+=(const DetectionScore& other);
};

// Both lists sorted without repeats (as Detection::pairs are). Throws std::invalid_argument
// otherwise, since an unsorted list would be miscounted silently.
[[nodiscard]] DetectionScore scoreDetection(const std::vector<LeafPairId>& truth,
                                            const std::vector<LeafPairId>& found);

}  // namespace recode::verify
