#pragma once
// The pairs `recode verify` checks: every pair of blocks of different objects of a scene, the
// built-in pair, or the generated suite (verify::generatePairSuite).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/scene/scene.hpp"

namespace recode::app {

// A scene's pairs share their blocks' world meshes (made once per block), so the memory of a
// scene's pairs follows its blocks and kMaxVerifiedPairs, not blocks squared.
struct PairToVerify {
  std::string label;  // "A name / B name", or the suite's label
  std::shared_ptr<const core::TriangleMesh> a, b;
  core::FrameSpec frame;
};

// The most pairs `recode verify SCENE` checks: every pair of blocks of two objects is checked
// (also pairs far apart), so a scene of n single-block objects has n(n-1)/2; above this the
// command refuses the scene before checking any (docs/cli.md).
inline constexpr long long kMaxVerifiedPairs = 100'000;

struct VerifyPairs {
  std::string source;  // the scene file, "built-in pair" or "suite (N pairs, seed S, width W)"
  std::vector<PairToVerify> pairs;
};

// Every pair of convex blocks (leaves) of two different objects, posed at `frame`, each pair
// with its own frame from the scene's view over the two blocks' bounds (as `recode pair` frames
// its pair). Throws core::SceneError at "objects" when there are over kMaxVerifiedPairs.
[[nodiscard]] VerifyPairs scenePairs(const core::Scene& scene,
                                     const core::FrameOverrides& overrides, int frame = 0);

// The generated suite; `overrides` may not be given (the suite sets its own frames).
[[nodiscard]] VerifyPairs suitePairs(int count, unsigned seed, int width);

}  // namespace recode::app
