// The comb experiments (the paper's Figures 9 and 10): two rows ("combs") of five identical
// cones, A standing apex up on z = 0, B hanging apex down above it; B moves.
//
//   translate: B moves straight down. Aligned, the tips meet on the cones' axes: the cones'
//              boxes touch nothing before the contact frame (each tip lies on its box), then
//              all five tip pairs meet in the same frame. Offset (B shifted half a spacing
//              along x), B's cones slide down between A's with their boxes overlapping for
//              many frames, until the slanted sides meet.
//   rotate:    B's tips reach just below A's (by kTipOverlap) and B turns about the vertical
//              axis through A's middle cone. Aligned, the middle tips stay in contact and all
//              five pairs meet at 0 and 180 degrees; offset, the tips circle between A's and
//              never touch, while boxes keep crossing.
#include <cmath>
#include <string>

#include "scene_builder.hpp"

namespace recode::core::detail {

namespace {

constexpr double kRadius = 0.5;
constexpr double kHeight = 2.0;
constexpr double kSpacing = 1.5;  // more than 2 * kRadius: neighbours' boxes never meet
constexpr int kCones = 5;
constexpr double kSpeed = 0.1;        // translation, world units per frame
constexpr double kTipOverlap = 0.05;  // depth of the tips' overlap (rotate; translate at contact)
constexpr int kContactFrame = 10;     // translate-aligned: the first frame with contact
constexpr double kTurnRate = 5.0;     // rotate: degrees per frame

Json comb(const std::string& name, bool hanging, double offset) {
  Json children = Json::array();
  for (int i = 0; i < kCones; ++i) {
    Json cone;
    cone["name"] = "cone " + std::to_string(i);
    cone["part"] = "cone";
    cone["position"] = vec((i - kCones / 2) * kSpacing + offset, 0, 0);
    if (hanging)
      cone["rotation_deg"] = vec(180, 0, 0);  // apex down, base at the comb's origin
    children.push_back(cone);
  }
  Json object;
  object["name"] = name;
  object["children"] = children;
  return object;
}

}  // namespace

Json makeCombScene(bool rotate, bool offset, int trianglesPerBlock) {
  Json scene;
  Json view;
  view["axis"] = "y";  // from the side: the rows and the cones' axes in the image plane
  view["pixel_size"] = 0.002;
  scene["view"] = view;
  const double shift = offset ? kSpacing / 2.0 : 0.0;
  Json b = comb("comb B", true, shift);
  Json motion;
  if (!rotate) {
    // B's tips at height apex(k) = start - kSpeed * k. Aligned: kTipOverlap above A's tips
    // one frame before the contact frame, kTipOverlap below at it (so the boxes are apart
    // until then). Offset: the slanted sides meet when B's tips reach
    // kHeight * (1 - offset / kRadius) = -1; B starts with its tips just below A's.
    const double start =
        offset ? kHeight - kTipOverlap : kHeight - kTipOverlap + kSpeed * kContactFrame;
    b["position"] = vec(0, 0, start + kHeight);
    motion["velocity"] = vec(0, 0, -kSpeed);
    scene["frames"] = offset ? 32 : kContactFrame + 6;
  } else {
    b["position"] = vec(0, 0, 2.0 * kHeight - kTipOverlap);
    motion["angular_velocity_deg"] = vec(0, 0, kTurnRate);
    scene["frames"] = static_cast<int>(std::lround(360.0 / kTurnRate));
  }
  b["motion"] = motion;
  Json cone;
  cone["shape"] = coneBlock(kRadius, kHeight, trianglesPerBlock).shape;
  scene["parts"]["cone"] = cone;
  scene["objects"] = Json::array({comb("comb A", false, 0.0), b});
  return scene;
}

}  // namespace recode::core::detail
