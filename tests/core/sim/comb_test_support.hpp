#pragma once
// comb-translate-aligned's contact frame, worked out from the scene's own numbers rather than
// from any detector, for every suite that checks what happens there (the run, the peers).

#include <catch2/catch.hpp>

#include "recode/scene/scene.hpp"

namespace recode::test {

// The tips of comb B hang this far below its origin; the tips of comb A stand this high.
inline constexpr double kCombConeHeight = 2.0;

// Height of B's tips above A's tips at frame k (<= 0: they meet).
inline double combTipGap(const core::Scene& scene, int frame) {
  REQUIRE(scene.objects.size() == 2);
  const core::SceneObject& b = scene.objects[1];
  REQUIRE(b.motion.has_value());
  return b.position.z() + b.motion->velocity.z() * frame - kCombConeHeight - kCombConeHeight;
}

// The first frame at which B's tips, moving with B's velocity, reach A's.
inline int combContactFrame(const core::Scene& scene) {
  for (int k = 0; k < 1000; ++k)
    if (combTipGap(scene, k) <= 0.0)
      return k;
  FAIL("the combs never meet");
  return -1;
}

}  // namespace recode::test
