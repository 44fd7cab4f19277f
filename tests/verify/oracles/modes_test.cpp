// The adaptive and conservative modes (core/refine) against CGAL's exact verdict on a third of
// the generated suite at width 64, where the reference misses pairs by resolution. The promises
// checked are the modes' own (docs/algorithm.md, "Beyond the paper"): the conservative mode
// misses nothing and every extra is within its bound; the adaptive mode misses nothing and
// reports nothing CGAL calls apart, apart from the apart_at_limit verdicts it counts.

#include <catch2/catch.hpp>

#include "recode/verify/cgal_oracle.hpp"
#include "recode/verify/mode_check.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;

namespace {

verify::ModeCounts checkSuiteThird(core::AdaptivePairTester& tester) {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  verify::ModeCounts counts;
  for (std::size_t i = 0; i < suite.size(); i += 3) {
    const verify::SuitePair& p = suite[i];
    const bool exact = verify::exactlyIntersect(p.a, p.b);
    const verify::ModeCheck check = verify::checkModes(p.a, p.b, p.frame, exact, tester);
    INFO(p.label);
    counts.add(check);
  }
  return counts;
}

}  // namespace

TEST_CASE("on a third of the suite the modes keep their promises where the reference misses") {
  core::AdaptivePairTester tester;
  const verify::ModeCounts c = checkSuiteThird(tester);
  INFO("truth " << c.truth << "; reference missed " << c.reference.missed << ", extra "
                << c.reference.extra << "; adaptive missed " << c.adaptive.missed << ", extra "
                << c.adaptive.extra << ", at limit " << c.apartAtLimit << "; conservative missed "
                << c.conservative.missed << ", extra " << c.conservative.extra);
  CHECK(c.pairs == 168);
  // The subset is worth checking: the reference misses pairs here.
  CHECK(c.reference.missed > 10);
  CHECK(c.conservative.missed == 0);
  CHECK(c.conservativeExtrasBeyondBound == 0);
  CHECK(c.adaptive.missed == 0);
  // Its only extras are the reference's touches within depth rounding (faces 1e-7 apart seen
  // as touching) that it keeps; it adds none.
  CHECK(c.adaptive.extra <= c.reference.extra);
  // Every miss of the reference that the adaptive mode found took a finer frame.
  CHECK(c.seenFiner == c.reference.missed - c.apartAtLimitTrue);
}

TEST_CASE("without refinement levels the adaptive mode misses what the reference misses") {
  // The check can fail: with maxLevel 0 there is nothing to refine to, so every resolution
  // miss of the reference stays a miss or becomes apart_at_limit.
  core::RefineLimits limits;
  limits.maxLevel = 0;
  core::AdaptivePairTester tester(limits);
  const verify::ModeCounts c = checkSuiteThird(tester);
  CHECK(c.seenFiner == 0);
  CHECK(c.adaptive.missed + c.apartAtLimitTrue == c.reference.missed);
  CHECK(c.adaptive.missed + c.apartAtLimitTrue > 10);
}
