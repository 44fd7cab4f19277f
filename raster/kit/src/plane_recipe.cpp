#include "plane_recipe.hpp"

namespace recode::kit::detail {

namespace {

PlaneRecipe anchoredAt(AnchorVertex a) {
  PlaneRecipe r;
  r.anchor = a;
  return r;
}

PlaneRecipe startingFrom(PlaneOrigin o) {
  PlaneRecipe r;
  r.origin = o;
  return r;
}

PlaneRecipe fusing(unsigned fused) {
  PlaneRecipe r;
  r.fused = fused;
  return r;
}

PlaneRecipe inFloat(unsigned stages) {
  PlaneRecipe r;
  r.inFloat = stages;
  return r;
}

}  // namespace

PlaneRecipe planeRecipe(Variant v) {
  switch (v) {
    case Variant::AnchorRotated:
      return anchoredAt(AnchorVertex::Second);
    case Variant::AnchorSorted:
      return anchoredAt(AnchorVertex::Lowest);
    case Variant::PlaneFromOrigin:
      return startingFrom(PlaneOrigin::FramebufferOrigin);
    case Variant::IncrementalFromPixel00:
      return startingFrom(PlaneOrigin::SteppedFromPixel00);
    case Variant::FmaPlane:
      return fusing(kFuseSlopeXLeft | kFuseSlopeYLeft | kFuseEvalX | kFuseEvalY);
    case Variant::FloatPlane:
      return inFloat(kFloatSetup | kFloatEvaluation);
    default:
      return {};
  }
}

Rounding rounding(Variant v) {
  switch (v) {
    case Variant::QuantiseHalfUp:
      return Rounding::HalfUp;
    case Variant::Quantise2To24:
      return Rounding::Scale2To24;
    default:
      return Rounding::NearestEven;
  }
}

}  // namespace recode::kit::detail
