// Depth arithmetic: one vector aimed at each reading of section 5's depth arithmetic and of the
// 24-bit quantisation (variants.hpp, from the anchor to the rounding), each drawn from a mix of
// planes on which those readings round their own way:
//   - a plane across the frame sloped along both axes whose exact value is a quantisation tie at
//     every sample (slopedTiePlane), or one sloped along one axis (tiePlane);
//   - steep slivers through samples at a tie, near one or at random depths, anchored up to 32768
//     pixels away or a few pixels long (addSteepSliver);
//   - a depth clear whose product d * 16777215 rounds to a tie k + 0.5, k even or odd, the exact
//     product a little above or below it.
// Every vector is kept only when its target variant gets other bits than the contract.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

// The depth readings, those that the other vectors catch least first: vector `index` aims at
// the index-th (cyclically), so a share larger than the list aims twice at the first ones.
const std::vector<Variant> kTargets = {
    // Rarely caught by chance: a single fused multiply-add or one other order of the sum
    // changes the depth by an ulp, which matters only at a tie.
    Variant::FmaSlopeXLeft,
    Variant::FmaSlopeXRight,
    Variant::FmaSlopeYLeft,
    Variant::FmaSlopeYRight,
    Variant::FmaEvalX,
    Variant::EvalYFirst,
    Variant::EvalOffsetsFirst,
    Variant::AnchorPixelCentre,
    Variant::SlopeDivideTerms,
    Variant::SlopeReciprocal,
    Variant::SlopeEdgeOverArea,
    Variant::SlopeReciprocalTerms,
    Variant::EvalDivideTerms,
    Variant::AnchorHighest,
    Variant::AnchorSorted,
    // The others, in the order of variants.hpp.
    Variant::AnchorRotated,
    Variant::AnchorThird,
    Variant::PlaneFromOrigin,
    Variant::PlaneFromPixel00,
    Variant::IncrementalFromPixel00,
    Variant::SlopeDepthOverArea,
    Variant::SlopeEdgeTimesReciprocal,
    Variant::SlopeDepthTimesReciprocal,
    Variant::EvalDivideSum,
    Variant::EvalOffsetsOverArea,
    Variant::Barycentric,
    Variant::BarycentricWeights,
    Variant::FmaPlane,
    Variant::FmaEvalY,
    Variant::FloatPlane,
    Variant::FloatDepthInputs,
    Variant::FloatArea,
    Variant::FloatSlopes,
    Variant::FloatStoredSlopes,
    Variant::FloatEvaluation,
    Variant::FloatDepthOutput,
    Variant::QuantiseHalfUp,
    Variant::QuantiseHalfAway,
    Variant::QuantiseHalfDown,
    Variant::QuantiseTruncate,
    Variant::QuantiseCeil,
    Variant::QuantiseFloat,
    Variant::QuantiseExactProduct,
    Variant::Quantise2To24,
    Variant::Quantise2To24Truncate,
};

// A double d whose product d * 16777215, rounded to double, is exactly k + 0.5 (k either even
// or odd); the exact product lies a little off the tie, on either side.
double tiedClearValue(Rng& rng) {
  for (;;) {
    const double k = static_cast<double>(rng.uniform(1, 16777213));
    const double d = (k + 0.5) / 16777215.0;
    for (const double candidate : {d, std::nextafter(d, 0.0), std::nextafter(d, 1.0)}) {
      if (candidate * 16777215.0 == k + 0.5)
        return candidate;
    }
  }
}

}  // namespace

Candidate depthArithmetic(Rng& rng, int index) {
  const Variant target = kTargets[static_cast<std::size_t>(index) % kTargets.size()];
  Candidate c;
  c.width = 16;
  c.height = 16;
  c.targets = {target};
  c.commands = countFacingsKeepDepth();
  std::string what;
  const bool clear = rng.chance(30);
  if (clear) {
    c.commands.push_back(cmd::ClearDepth{tiedClearValue(rng)});
    what += " a depth clear whose d * 16777215 rounds to a tie k + 0.5;";
  }
  const long long plane = rng.uniform(0, 99);
  if (plane < 65) {
    // Over the top half only after a clear, so that the clear's bits stay in the bottom half.
    if (clear)
      c.commands.push_back(cmd::Scissor{{0, c.height / 2, c.width, c.height}});
    if (plane < 50) {
      c.commands.push_back(slopedTiePlane(rng, c.width, c.height));
      what += " a plane sloped along both axes, exactly at a tie k + 0.5 at every sample;";
    } else {
      c.commands.push_back(tiePlane(rng, c.width, c.height, rng.chance(50), rng.chance(50)));
      what += " a plane along one axis, exactly at a tie k + 0.5 at every sample;";
    }
    if (clear)
      c.commands.push_back(cmd::Scissor{{0, 0, c.width, c.height}});
  }
  cmd::Draw d;
  const long long n = rng.uniform(1, 4);
  for (long long k = 0; k < n; ++k)
    addSteepSliver(rng, c.width, c.height, d);
  c.commands.push_back(std::move(d));
  c.description =
      "Depth arithmetic:" + what +
      " steep slivers through sample points (a few fixed-point units thick), up to 32768 "
      "pixels long or a few pixels, along lines at or near a quantisation tie or at random "
      "depths, submitted from any vertex. Kept because " +
      std::string(variantName(target)) + " rounds them to other depth bits.";
  return c;
}

}  // namespace recode::kit::detail
