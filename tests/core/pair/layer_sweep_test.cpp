// The layered pair's sweep at one pixel, on depths written by hand: how entries and exits pair
// into the intervals inside a mesh, how two meshes' intervals meet, and containment.

#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "layer_sweep.hpp"

using recode::core::detail::DepthInterval;
using recode::core::detail::insideIntervals;
using recode::core::detail::intersectIntervals;
using recode::core::detail::liesWithin;
using recode::core::detail::totalLength;

namespace {

std::vector<DepthInterval> inside(std::vector<std::uint32_t> entries,
                                  std::vector<std::uint32_t> exits, int* inverted = nullptr) {
  std::vector<DepthInterval> out{{7, 7}};  // cleared by the call
  const int n = insideIntervals(entries, exits, out);
  if (inverted)
    *inverted = n;
  return out;
}

std::vector<DepthInterval> meet(const std::vector<DepthInterval>& a,
                                const std::vector<DepthInterval>& b) {
  std::vector<DepthInterval> out{{1, 2}};
  intersectIntervals(a, b, out);
  return out;
}

}  // namespace

TEST_CASE("a torus seen across its hole: two intervals, the i-th entry with the i-th exit") {
  int inverted = -1;
  CHECK(inside({10, 50}, {20, 60}, &inverted) == std::vector<DepthInterval>{{10, 20}, {50, 60}});
  CHECK(inverted == 0);
  CHECK(inside({}, {}).empty());
}

TEST_CASE("nested shells: entries and exits sorted apart still pair into the solid") {
  // An outward ball inside an outward ball: entries 10 (outer) and 30 (inner), exits 40 (inner)
  // and 80 (outer). Pairing the sorted lists gives [10, 40] and [30, 80], merged to [10, 80].
  CHECK(inside({10, 30}, {40, 80}) == std::vector<DepthInterval>{{10, 80}});
  // A hollow ball: entry 10, exit 30 into the cavity, entry 60 out of it, exit 80.
  CHECK(inside({10, 60}, {30, 80}) == std::vector<DepthInterval>{{10, 30}, {60, 80}});
}

TEST_CASE("an entry rounded beyond its exit is counted and its pair taken between the two") {
  int inverted = -1;
  CHECK(inside({21}, {20}, &inverted) == std::vector<DepthInterval>{{20, 21}});
  CHECK(inverted == 1);
}

TEST_CASE("walls that touch after rounding merge; one step apart stays apart") {
  CHECK(inside({10, 20}, {20, 30}) == std::vector<DepthInterval>{{10, 30}});
  CHECK(inside({10, 21}, {20, 30}) == std::vector<DepthInterval>{{10, 20}, {21, 30}});
}

TEST_CASE("two meshes' intervals: their common depths, touching as a one-depth interval") {
  const std::vector<DepthInterval> a{{10, 20}, {50, 60}};
  CHECK(meet(a, {{15, 55}}) == std::vector<DepthInterval>{{15, 20}, {50, 55}});
  CHECK(meet(a, {{20, 50}}) == std::vector<DepthInterval>{{20, 20}, {50, 50}});
  CHECK(meet(a, {{21, 49}}).empty());
  CHECK(meet(a, {{0, 5}, {12, 13}, {18, 52}, {59, 90}}) ==
        std::vector<DepthInterval>{{12, 13}, {18, 20}, {50, 52}, {59, 60}});
  CHECK(meet({}, a).empty());
  CHECK(totalLength(meet(a, {{15, 55}})) == 10u);
  CHECK(totalLength(meet(a, {{20, 50}})) == 0u);
}

TEST_CASE("containment: every interval of one inside an interval of the other") {
  const std::vector<DepthInterval> outer{{10, 30}, {60, 80}};
  CHECK(liesWithin(std::vector<DepthInterval>{{12, 20}, {60, 80}}, outer));
  CHECK(liesWithin(std::vector<DepthInterval>{}, outer));
  CHECK_FALSE(liesWithin(std::vector<DepthInterval>{{25, 65}}, outer));  // across the gap
  CHECK_FALSE(liesWithin(std::vector<DepthInterval>{{12, 20}, {79, 81}}, outer));
  CHECK_FALSE(liesWithin(std::vector<DepthInterval>{{40, 50}}, outer));
  CHECK_FALSE(liesWithin(outer, std::vector<DepthInterval>{}));
}
