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

PlaneRecipe withSlopes(SlopeForm s) {
  PlaneRecipe r;
  r.slopes = s;
  return r;
}

PlaneRecipe evaluatedAs(EvalForm e) {
  PlaneRecipe r;
  r.eval = e;
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
    case Variant::AnchorThird:
      return anchoredAt(AnchorVertex::Third);
    case Variant::AnchorSorted:
      return anchoredAt(AnchorVertex::Lowest);
    case Variant::AnchorHighest:
      return anchoredAt(AnchorVertex::Highest);
    case Variant::AnchorPixelCentre:
      return startingFrom(PlaneOrigin::AnchorPixelCentre);
    case Variant::PlaneFromOrigin:
      return startingFrom(PlaneOrigin::FramebufferOrigin);
    case Variant::PlaneFromPixel00:
      return startingFrom(PlaneOrigin::Pixel00);
    case Variant::IncrementalFromPixel00:
      return startingFrom(PlaneOrigin::SteppedFromPixel00);
    case Variant::SlopeDivideTerms:
      return withSlopes(SlopeForm::DivideTerms);
    case Variant::SlopeEdgeOverArea:
      return withSlopes(SlopeForm::EdgeOverArea);
    case Variant::SlopeDepthOverArea:
      return withSlopes(SlopeForm::DepthOverArea);
    case Variant::SlopeReciprocal:
      return withSlopes(SlopeForm::Reciprocal);
    case Variant::SlopeReciprocalTerms:
      return withSlopes(SlopeForm::ReciprocalTerms);
    case Variant::SlopeEdgeTimesReciprocal:
      return withSlopes(SlopeForm::EdgeTimesReciprocal);
    case Variant::SlopeDepthTimesReciprocal:
      return withSlopes(SlopeForm::DepthTimesReciprocal);
    case Variant::EvalYFirst:
      return evaluatedAs(EvalForm::YThenX);
    case Variant::EvalOffsetsFirst:
      return evaluatedAs(EvalForm::OffsetsFirst);
    case Variant::EvalDivideSum:
      return evaluatedAs(EvalForm::DivideSum);
    case Variant::EvalDivideTerms:
      return evaluatedAs(EvalForm::DivideTerms);
    case Variant::EvalOffsetsOverArea:
      return evaluatedAs(EvalForm::OffsetsOverArea);
    case Variant::Barycentric:
      return evaluatedAs(EvalForm::Barycentric);
    case Variant::BarycentricWeights:
      return evaluatedAs(EvalForm::BarycentricWeights);
    case Variant::FmaPlane:
      return fusing(kFuseSlopeXLeft | kFuseSlopeYLeft | kFuseEvalX | kFuseEvalY);
    case Variant::FmaSlopeXLeft:
      return fusing(kFuseSlopeXLeft);
    case Variant::FmaSlopeXRight:
      return fusing(kFuseSlopeXRight);
    case Variant::FmaSlopeYLeft:
      return fusing(kFuseSlopeYLeft);
    case Variant::FmaSlopeYRight:
      return fusing(kFuseSlopeYRight);
    case Variant::FmaEvalX:
      return fusing(kFuseEvalX);
    case Variant::FmaEvalY:
      return fusing(kFuseEvalY);
    case Variant::FloatPlane:
      return inFloat(kFloatSetup | kFloatEvaluation);
    case Variant::FloatDepthInputs:
      return inFloat(kFloatDepthInputs);
    case Variant::FloatArea:
      return inFloat(kFloatArea);
    case Variant::FloatSlopes:
      return inFloat(kFloatSetup);
    case Variant::FloatStoredSlopes:
      return inFloat(kFloatStoredSlopes);
    case Variant::FloatEvaluation:
      return inFloat(kFloatEvaluation);
    case Variant::FloatDepthOutput:
      return inFloat(kFloatOutput);
    default:
      return {};
  }
}

Rounding rounding(Variant v) {
  switch (v) {
    case Variant::QuantiseHalfUp:
      return Rounding::HalfUp;
    case Variant::QuantiseHalfAway:
      return Rounding::HalfAway;
    case Variant::QuantiseHalfDown:
      return Rounding::HalfDown;
    case Variant::QuantiseTruncate:
      return Rounding::Truncate;
    case Variant::QuantiseCeil:
      return Rounding::Ceil;
    case Variant::QuantiseFloat:
      return Rounding::FloatMultiply;
    case Variant::QuantiseExactProduct:
      return Rounding::ExactProduct;
    case Variant::Quantise2To24:
      return Rounding::Scale2To24;
    case Variant::Quantise2To24Truncate:
      return Rounding::Scale2To24Truncate;
    default:
      return Rounding::NearestEven;
  }
}

}  // namespace recode::kit::detail
