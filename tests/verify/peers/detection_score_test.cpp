// Scoring detections against the exact judge: hand-made lists with known missed and extra
// pairs, the identity found - extra + missed == truth, and unsorted input refused.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "recode/verify/detection_score.hpp"

using recode::verify::DetectionScore;
using recode::verify::LeafPairId;
using recode::verify::scoreDetection;

TEST_CASE("scoreDetection counts missed and extra pairs of hand-made lists", "[bench][score]") {
  const LeafPairId p{0, 1, 1, 1}, q{0, 1, 2, 3}, r{0, 2, 1, 1}, s{3, 4, 5, 6};
  SECTION("identical") {
    const DetectionScore d = scoreDetection({p, q}, {p, q});
    CHECK(d.truth == 2);
    CHECK(d.found == 2);
    CHECK(d.missed == 0);
    CHECK(d.extra == 0);
  }
  SECTION("one missed, one extra") {
    const DetectionScore d = scoreDetection({p, q, s}, {p, r, s});
    CHECK(d.missed == 1);  // q
    CHECK(d.extra == 1);   // r
  }
  SECTION("nothing found") {
    const DetectionScore d = scoreDetection({p, q, r}, {});
    CHECK(d.missed == 3);
    CHECK(d.extra == 0);
  }
  SECTION("nothing true") {
    const DetectionScore d = scoreDetection({}, {q, s});
    CHECK(d.missed == 0);
    CHECK(d.extra == 2);
  }
}

TEST_CASE("scoreDetection agrees with set difference on random lists", "[bench][score]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> small(0, 3);
  DetectionScore total;
  for (int trial = 0; trial < 500; ++trial) {
    std::set<LeafPairId> truth, found;
    for (int i = 0; i < 12; ++i) {
      truth.insert({small(rng), small(rng), 4 + small(rng), small(rng)});
      found.insert({small(rng), small(rng), 4 + small(rng), small(rng)});
    }
    long long missed = 0, extra = 0;
    for (const LeafPairId& t : truth)
      missed += found.count(t) == 0 ? 1 : 0;
    for (const LeafPairId& f : found)
      extra += truth.count(f) == 0 ? 1 : 0;
    const DetectionScore d =
        scoreDetection({truth.begin(), truth.end()}, {found.begin(), found.end()});
    CHECK(d.missed == missed);
    CHECK(d.extra == extra);
    CHECK(d.found - d.extra + d.missed == d.truth);
    total += d;
  }
  CHECK(total.found - total.extra + total.missed == total.truth);
  CHECK(total.missed > 0);
  CHECK(total.extra > 0);
}

TEST_CASE("scoreDetection refuses lists that are not sorted without repeats", "[bench][score]") {
  const LeafPairId p{0, 1, 1, 1}, q{0, 1, 2, 3};
  CHECK_THROWS_AS(scoreDetection({q, p}, {}), std::invalid_argument);
  CHECK_THROWS_AS(scoreDetection({}, {p, p}), std::invalid_argument);
}
