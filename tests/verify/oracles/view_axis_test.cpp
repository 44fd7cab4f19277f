// The adaptive view axis (core/refine view_axis_choice.hpp) against CGAL on a third of the
// generated suite at width 64: whatever axis a rule picks, RECODE in the rebuilt frame reports
// no pair that CGAL calls apart beyond the judge's tolerances (no Disagree at all, as in the
// scene axis's frames), and the rules do change the axis of some pairs.

#include <catch2/catch.hpp>

#include "recode/raster/cpu_device.hpp"
#include "recode/refine/view_axis_choice.hpp"
#include "recode/verify/cgal_oracle.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;

namespace {

struct RuleCounts {
  long long pairs = 0, changed = 0, disagree = 0;
};

RuleCounts judgeSuiteThird(core::ViewAxisRule rule) {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  RuleCounts c;
  for (std::size_t i = 0; i < suite.size(); i += 3) {
    const verify::SuitePair& p = suite[i];
    core::Aabb bounds = core::boundingBox(p.a);
    bounds.extend(core::boundingBox(p.b));
    const core::ViewAxis axis = core::chooseViewAxis(
        rule, p.frame.axis, core::axisChoiceInput(p.a, p.b, core::framePixelSize(p.frame)));
    core::PairRequest request;
    request.frame = core::frameAlongAxis(p.frame, axis, bounds);
    raster::CpuDevice device(request.frame.width, request.frame.height);
    const core::PairResult result = core::collidePair(device, p.a, p.b, request);
    const verify::ExactIntersection exact = verify::exactIntersection(p.a, p.b);
    const verify::CgalJudgement j = verify::judgePair(exact, request.frame, p.a, p.b, result);
    INFO(p.label << " along " << core::toString(axis) << ": " << j.reason);
    CHECK(j.verdict != verify::VerdictCheck::Disagree);
    ++c.pairs;
    c.changed += axis != p.frame.axis ? 1 : 0;
    c.disagree += j.verdict == verify::VerdictCheck::Disagree ? 1 : 0;
  }
  return c;
}

}  // namespace

TEST_CASE("every view axis rule: no pair CGAL calls apart is reported beyond the tolerances") {
  for (const core::ViewAxisRule rule :
       {core::ViewAxisRule::FewestMor, core::ViewAxisRule::WidestOverlap,
        core::ViewAxisRule::Separating, core::ViewAxisRule::ThinOverlap}) {
    INFO("rule " << core::toString(rule));
    const RuleCounts c = judgeSuiteThird(rule);
    CHECK(c.pairs == 168);
    CHECK(c.disagree == 0);
    // The rule is exercised: it moves a good share of the pairs off the scene axis.
    CHECK(c.changed > 10);
  }
}
