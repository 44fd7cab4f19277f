#include "reading_class.hpp"

namespace recode::conformance {

// No default: a reading added to kit::Variant is an error here (-Wswitch) until it is classed.
ReadingClass classOf(kit::Variant v) {
  using kit::Variant;
  switch (v) {
    case Variant::Contract:
      return {Stage::DepthValue, std::nullopt};
    case Variant::TopLeftFill:
      return {Stage::Coverage, Freedom::TieRule};
    case Variant::EdgeFloat:
    case Variant::SubPixel4Nearest:
    case Variant::SubPixel4Floor:
    case Variant::SubPixel4Ceil:
    case Variant::SubPixel4HalfUp:
    case Variant::SubPixel6Nearest:
      return {Stage::Coverage, Freedom::SubPixelPrecision};
    // The anchor, the slopes, the evaluation, fusion and single precision.
    case Variant::AnchorRotated:
    case Variant::AnchorThird:
    case Variant::AnchorSorted:
    case Variant::AnchorHighest:
    case Variant::AnchorPixelCentre:
    case Variant::PlaneFromOrigin:
    case Variant::PlaneFromPixel00:
    case Variant::IncrementalFromPixel00:
    case Variant::SlopeDivideTerms:
    case Variant::SlopeEdgeOverArea:
    case Variant::SlopeDepthOverArea:
    case Variant::SlopeReciprocal:
    case Variant::SlopeReciprocalTerms:
    case Variant::SlopeEdgeTimesReciprocal:
    case Variant::SlopeDepthTimesReciprocal:
    case Variant::EvalYFirst:
    case Variant::EvalOffsetsFirst:
    case Variant::EvalDivideSum:
    case Variant::EvalDivideTerms:
    case Variant::EvalOffsetsOverArea:
    case Variant::Barycentric:
    case Variant::BarycentricWeights:
    case Variant::FmaPlane:
    case Variant::FmaSlopeXLeft:
    case Variant::FmaSlopeXRight:
    case Variant::FmaSlopeYLeft:
    case Variant::FmaSlopeYRight:
    case Variant::FmaEvalX:
    case Variant::FmaEvalY:
    case Variant::FloatPlane:
    case Variant::FloatDepthInputs:
    case Variant::FloatArea:
    case Variant::FloatSlopes:
    case Variant::FloatStoredSlopes:
    case Variant::FloatEvaluation:
    case Variant::FloatDepthOutput:
      return {Stage::DepthValue, Freedom::DepthInterpolation};
    case Variant::QuantiseHalfUp:
    case Variant::QuantiseHalfAway:
    case Variant::QuantiseHalfDown:
    case Variant::QuantiseTruncate:
    case Variant::QuantiseCeil:
    case Variant::QuantiseFloat:
    case Variant::QuantiseExactProduct:
    case Variant::Quantise2To24:
    case Variant::Quantise2To24Truncate:
      return {Stage::Quantisation, Freedom::DepthConversion};
    case Variant::IncrWraps:
    case Variant::DecrWraps:
    case Variant::IgnoreValueMask:
      return {Stage::Stencil, std::nullopt};
    case Variant::StencilClearIgnoresWriteMask:
    case Variant::DepthClearIgnoresWriteMask:
    case Variant::ClearIgnoresScissor:
      return {Stage::Clear, std::nullopt};
    case Variant::SwappedFacing:
      return {Stage::Facing, std::nullopt};
    case Variant::StrictLimits:
      return {Stage::Validation, std::nullopt};
  }
  return {Stage::DepthValue, std::nullopt};  // unreached: every enumerator has a case
}

}  // namespace recode::conformance
