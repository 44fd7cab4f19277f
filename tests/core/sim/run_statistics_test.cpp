// Table 2 statistics from frame reports: totals in seconds, means and population standard
// deviations in milliseconds, counters summed, the first contact frame.

#include <catch2/catch.hpp>

#include <cmath>

#include "recode/sim/run_statistics.hpp"

using namespace recode::core;

TEST_CASE("run statistics: NTR TNF TTF ATF DTF TTC ATC DTC and counters", "[stats]") {
  RunStatisticsAccumulator acc;
  const double frameUs[] = {1000, 2000, 3000, 6000};
  const double collisionUs[] = {500, 500, 1500, 1500};
  for (int k = 0; k < 4; ++k) {
    FrameReport r;
    r.frame = k;
    r.frameUs = frameUs[k];
    r.collisionUs = collisionUs[k];
    r.boxTests = 10 * k;
    r.pairTests = k;
    r.objectPairs = 2;
    r.stencilPixelsRead = 100;
    r.depthPixelsRead = 7;
    if (k >= 2)
      r.contacts.resize(static_cast<std::size_t>(k));  // 2 at frame 2, 3 at frame 3
    acc.add(r);
  }
  const RunStatistics s = acc.result(1234);
  CHECK(s.triangles == 1234);
  CHECK(s.frames == 4);
  CHECK(s.totalFrameS == Approx(0.012));
  CHECK(s.meanFrameMs == Approx(3.0));
  // Deviations from 3 ms: -2, -1, 0, 3: variance (4 + 1 + 0 + 9) / 4 = 3.5.
  CHECK(s.sdFrameMs == Approx(std::sqrt(3.5)));
  CHECK(s.totalCollisionS == Approx(0.004));
  CHECK(s.meanCollisionMs == Approx(1.0));
  CHECK(s.sdCollisionMs == Approx(0.5));
  CHECK(s.boxTests == 60);
  CHECK(s.pairTests == 6);
  CHECK(s.objectPairs == 8);
  CHECK(s.stencilPixelsRead == 400);
  CHECK(s.depthPixelsRead == 28);
  CHECK(s.contacts == 5);
  CHECK(s.framesWithContact == 2);
  CHECK(s.firstContactFrame == 2);

  const RunStatistics none = RunStatisticsAccumulator().result(0);
  CHECK(none.frames == 0);
  CHECK(none.meanFrameMs == 0.0);
  CHECK(none.firstContactFrame == -1);
}
