// Convex blocks are the layered pair's special case: on the whole generated pair suite (every
// configuration, the hard ones included) the layered pair interferes at exactly the pixels
// where RECODE's passes find cases 3-6, in every MOR mode.

#include <catch2/catch.hpp>

#include "recode/pair/layered_pair.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;

TEST_CASE("the generated pair suite: the layered pair and RECODE's passes agree pixel for pixel",
          "[layered][suite]") {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  REQUIRE(suite.size() == 504);
  int colliding = 0, mismatched = 0;
  for (std::size_t i = 0; i < suite.size(); ++i) {
    const verify::SuitePair& p = suite[i];
    core::PairRequest request;
    request.frame = p.frame;
    request.mor = static_cast<core::MorMode>(i % 3);
    raster::CpuDevice device(p.frame.width, p.frame.height);
    const core::PairResult recode = core::collidePair(device, p.a, p.b, request);
    const core::LayeredPairResult layered = core::collideLayered(device, p.a, p.b, request);
    INFO(p.label);
    CHECK(layered.collide == recode.collide);
    CHECK(layered.interferingPixels == recode.interferingPixels);
    CHECK(layered.mor == recode.mor);
    CHECK(layered.layersA <= 1);
    CHECK(layered.layersB <= 1);
    if (layered.mor != recode.mor || recode.mor.empty())
      continue;
    long long differing = 0;
    for (int y = recode.mor.y0; y < recode.mor.y1; ++y)
      for (int x = recode.mor.x0; x < recode.mor.x1; ++x)
        differing +=
            (layered.interferes.at(x, y) != 0) != core::isInterfering(recode.caseMap.at(x, y));
    CHECK(differing == 0);
    mismatched += differing > 0 ? 1 : 0;
    colliding += recode.collide ? 1 : 0;
  }
  CHECK(mismatched == 0);
  CHECK(colliding > 100);  // 147 of the 504 pairs collide
}
