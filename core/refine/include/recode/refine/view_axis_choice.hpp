#pragma once
// The adaptive view axis (docs/algorithm.md, "Beyond the paper"): per pair, draw along the world
// axis that suits the pair instead of the scene's, at the same pixel size. The pair algorithm
// is unchanged; only the frame it is given differs. With ViewAxisRule::Scene (the default)
// every frame is the scene axis's, exactly as before.

#include <optional>
#include <string_view>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/obb.hpp"
#include "recode/geometry/projection.hpp"
#include "recode/pair/frame.hpp"

namespace recode::core {

// How a pair's view axis is chosen. The three adaptive rules look at the two blocks' world
// boxes; wx, wy, wz below are the widths of the intersection of the two AABBs along x, y, z.
enum class ViewAxisRule {
  Scene,          // the scene's (or the request's) axis: the reference behaviour
  FewestMor,      // the axis whose MOR (projected box intersection) has the fewest pixels:
                  // the one of the largest w, since the MOR's area is wx wy wz / w
  WidestOverlap,  // the axis whose projected box intersection is widest across its narrower
                  // side, in pixels: the one of the smallest w (the other two stay)
  Separating,     // the world axis nearest the direction of least overlap of the two blocks'
                  // OBBs (the separating-axis test's axis of least penetration)
  ThinOverlap,    // the scene axis, unless the boxes' intersection seen along it is narrower
                  // than kThinOverlapPixels pixels across: then WidestOverlap's axis
};

// ThinOverlap's threshold: a box intersection narrower than this many pixels across may hold a
// contact that falls between pixel centres (one that holds a disc of sqrt(2) pixels cannot);
// 2 was measured against 1, 4, 8 and 16 on the suite (docs/accuracy.md).
inline constexpr double kThinOverlapPixels = 2.0;

// The rule `--view-axis adaptive` stands for, chosen by measurement on the generated suite
// (docs/accuracy.md, "The adaptive view axis").
inline constexpr ViewAxisRule kAdaptiveViewAxisRule = ViewAxisRule::ThinOverlap;

// "scene", "fewest-mor", "widest-overlap", "separating", "thin-overlap".
[[nodiscard]] std::string_view toString(ViewAxisRule rule);
// The names above and "adaptive" (kAdaptiveViewAxisRule); nullopt for anything else.
[[nodiscard]] std::optional<ViewAxisRule> parseViewAxisRule(std::string_view name);
// The names parseViewAxisRule accepts, for error messages: "scene, adaptive, ...".
[[nodiscard]] std::string_view viewAxisRuleNames();

// What a rule looks at: each block's world AABB and an OBB around it, and the pixel size
// (world units; ThinOverlap's only).
struct AxisChoiceInput {
  Aabb boxA, boxB;
  Obb obbA, obbB;
  double pixelSize = 0.0;
};

// The input from two blocks' world meshes (their AABBs and fitObb boxes) and the pixel size.
[[nodiscard]] AxisChoiceInput axisChoiceInput(const TriangleMesh& a, const TriangleMesh& b,
                                              double pixelSize);

// The larger side of a frame's pixel, world units: the pixel size frameAlongAxis keeps.
[[nodiscard]] double framePixelSize(const FrameSpec& frame);

// The axis `rule` chooses. Pairs whose AABBs do not meet (closed) keep `sceneAxis`: the box
// test decides them apart along any axis. Among equally good axes the scene axis wins, then
// x before y before z.
[[nodiscard]] ViewAxis chooseViewAxis(ViewAxisRule rule, ViewAxis sceneAxis,
                                      const AxisChoiceInput& input);

// The frame along `axis` at `base`'s pixel size (the larger side of its pixel) over `bounds`
// (the objects the base frame was made for): `base` itself when the axis is base's, else
// frameFromPixelSize over defaultWindow(axis, bounds). Throws what frameFromPixelSize throws.
[[nodiscard]] FrameSpec frameAlongAxis(const FrameSpec& base, ViewAxis axis, const Aabb& bounds);

}  // namespace recode::core
