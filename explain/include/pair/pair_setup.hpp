#pragma once
// What `recode pair` and `recode explain` run on: two convex blocks in world coordinates and
// the frame, from a scene file's first two objects or from the built-in pair.

#include <filesystem>
#include <optional>
#include <string>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/scene/scene.hpp"

namespace recode::explain {

struct PairSetup {
  std::string source;  // the scene file, or "built-in pair"
  std::string nameA, nameB;
  core::TriangleMesh a, b;                // world coordinates
  bool closedA = false, closedB = false;  // a closed mesh, decided by the layered pair
  core::FrameSpec frame;

  // Whether the pair is decided by the layered pair (either object a closed mesh).
  [[nodiscard]] bool layered() const { return closedA || closedB; }
};

// The first two objects of the scene as A and B at frame 0, and the frame for them. Throws
// core::SceneError when the scene has fewer than two objects.
[[nodiscard]] PairSetup pairSetupFromScene(const core::Scene& scene,
                                           const core::FrameOverrides& overrides);

// core::resolveFrame for the scene's view, its errors naming where the frame came from:
// "--pixel-size: ...", "--resolution: ...", or the scene file at "view" (a SceneError).
[[nodiscard]] core::FrameSpec resolveFrameNamed(const core::Scene& scene, const core::Aabb& bounds,
                                                const core::FrameOverrides& overrides);

// A scene file when given, else core::builtinPairScene().
[[nodiscard]] PairSetup loadPairSetup(const std::optional<std::string>& scenePath,
                                      const core::FrameOverrides& overrides);

// "--resolution W" or "WxH" into overrides; throws std::invalid_argument naming the text.
[[nodiscard]] core::FrameOverrides parseResolution(const std::string& text);

}  // namespace recode::explain
