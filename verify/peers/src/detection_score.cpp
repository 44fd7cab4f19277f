// Missed and extra pairs of one frame, by a merge of two sorted lists.
#include "recode/verify/detection_score.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace recode::verify {

namespace {

void requireSortedUnique(const std::vector<LeafPairId>& pairs, const char* which) {
  const auto notIncreasing = [](const LeafPairId& a, const LeafPairId& b) { return !(a < b); };
  if (std::adjacent_find(pairs.begin(), pairs.end(), notIncreasing) != pairs.end())
    throw std::invalid_argument(std::string("scoreDetection: the ") + which +
                                " pairs are not sorted without repeats");
}

}  // namespace

DetectionScore& DetectionScore::operator+=(const DetectionScore& other) {
  truth += other.truth;
  found += other.found;
  missed += other.missed;
  extra += other.extra;
  return *this;
}

DetectionScore scoreDetection(const std::vector<LeafPairId>& truth,
                              const std::vector<LeafPairId>& found) {
  requireSortedUnique(truth, "true");
  requireSortedUnique(found, "found");
  DetectionScore score;
  score.truth = static_cast<long long>(truth.size());
  score.found = static_cast<long long>(found.size());
  auto t = truth.begin();
  auto f = found.begin();
  while (t != truth.end() || f != found.end()) {
    if (f == found.end() || (t != truth.end() && *t < *f)) {
      ++score.missed;
      ++t;
    } else if (t == truth.end() || *f < *t) {
      ++score.extra;
      ++f;
    } else {
      ++t;
      ++f;
    }
  }
  return score;
}

}  // namespace recode::verify
