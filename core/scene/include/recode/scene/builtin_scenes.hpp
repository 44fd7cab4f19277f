#pragma once
// Scenes built into the program, so the main job and the benchmarks need no data files.
// Each is also written out as JSON under data/scenes/, and a test holds the two equal.

#include "recode/scene/scene.hpp"

namespace recode::core {

// Two cones of radius 1 and height 2 (32 segments) tip to tip along z: A ("lower cone")
// stands on z = 0, B ("upper cone") is the same cone turned upside down with its apex 0.25
// into A's. Seen from the side along x at 256 x 256 pixels. data/scenes/cones-tip-to-tip.json.
[[nodiscard]] Scene builtinPairScene();

}  // namespace recode::core
