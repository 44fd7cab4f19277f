// The sort and sweep on boxes placed by hand: boxes that only touch are overlapping closed
// boxes, along the sweep axis as along the others, and are reported.

#include <catch2/catch.hpp>
#include <utility>
#include <vector>

#include "recode/sim/broad_phase.hpp"

using namespace recode;
using Eigen::Vector3d;

namespace {

core::Aabb box(const Vector3d& lo, const Vector3d& hi) {
  core::Aabb b;
  b.min = lo;
  b.max = hi;
  return b;
}

using Pairs = std::vector<std::pair<int, int>>;

}  // namespace

TEST_CASE("boxes that touch along the sweep axis are a pair") {
  // Centres spread along x: x is the sweep axis. Box 1 starts where box 0 ends, box 2 one
  // unit beyond box 1's end.
  const std::vector<core::Aabb> boxes = {box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1}),
                                         box({3, 0, 0}, {4, 1, 1})};
  core::SweepAndPrune sweep;
  const Pairs pairs = sweep.update(boxes);
  REQUIRE(sweep.axis() == 0);
  CHECK(pairs == Pairs{{0, 1}});
  // Box 0 meets box 1 on the sweep axis (their ends equal), box 1 does not meet box 2.
  CHECK(sweep.stats().intervalTests == 1);
}

TEST_CASE("boxes that touch across the sweep axis are a pair") {
  // Sweep axis x; boxes 0 and 1 share the face y = 1, boxes 0 and 2 the edge z = 1 of a face.
  const std::vector<core::Aabb> boxes = {box({0, 0, 0}, {4, 1, 1}), box({3, 1, 0}, {7, 2, 1}),
                                         box({6, -1, 1}, {9, 0, 2})};
  core::SweepAndPrune sweep;
  const Pairs pairs = sweep.update(boxes);
  REQUIRE(sweep.axis() == 0);
  CHECK(pairs == Pairs{{0, 1}});
  // Moved by hand so that box 2 touches box 1's corner edge (x = 7, y = 1, z = 1).
  const std::vector<core::Aabb> moved = {box({0, 0, 0}, {4, 1, 1}), box({3, 1, 0}, {7, 2, 1}),
                                         box({7, 2, 1}, {9, 3, 2})};
  CHECK(sweep.update(moved) == Pairs{{0, 1}, {1, 2}});
}

TEST_CASE("the sweep axis is the axis of greatest variance of the box centres") {
  // Unit boxes centred at (10, 0, 0) and (11, 4, 0): the centres' variances are 0.25 along x,
  // 4 along y and 0 along z, so y is swept. (Far from the origin along x, so that a variance
  // taken about the origin, or over one centre too many, would pick x.)
  const std::vector<core::Aabb> boxes = {box({9.5, -0.5, -0.5}, {10.5, 0.5, 0.5}),
                                         box({10.5, 3.5, -0.5}, {11.5, 4.5, 0.5})};
  core::SweepAndPrune sweep;
  CHECK(sweep.update(boxes).empty());  // they touch at x = 10.5 but lie apart along y
  CHECK(sweep.axis() == 1);
}

TEST_CASE("boxes that overlap along the sweep axis but not along x are no pair") {
  // Centres (0.5, 0.5), (5.5, 1), (0.5, 10.5) in (x, y): variance about 5.6 along x, 21.2
  // along y, so y is swept. Boxes 0 and 1 overlap along y and z but lie apart along x.
  const std::vector<core::Aabb> boxes = {box({0, 0, 0}, {1, 1, 1}), box({5, 0.5, 0}, {6, 1.5, 1}),
                                         box({0, 10, 0}, {1, 11, 1})};
  core::SweepAndPrune sweep;
  const Pairs pairs = sweep.update(boxes);
  REQUIRE(sweep.axis() == 1);
  CHECK(pairs.empty());
  // Only boxes 0 and 1 meet along y, and that one interval test finds them apart along x.
  CHECK(sweep.stats().intervalTests == 1);
}
