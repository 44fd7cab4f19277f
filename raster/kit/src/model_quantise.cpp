#include "model_quantise.hpp"

#include <algorithm>
#include <cmath>

namespace recode::kit::detail {

namespace {

constexpr double kDepthMax = 16777215.0;

// The exact product z (2^24 - 1) rounded half to even. Its double p is rounded already, and a
// half-integer below 2^52 is a double, so p lands on a tie k + 0.5 whenever the exact product is
// within half an ulp of it; the product's rounding error (exact: fma) says on which side the
// exact value lies.
double roundExactProduct(double z) {
  const double p = z * kDepthMax;
  const double error = std::fma(z, kDepthMax, -p);  // exact product minus p
  const double below = std::floor(p);
  if (p - below != 0.5 || error == 0.0)
    return std::nearbyint(p);
  return error > 0.0 ? below + 1.0 : below;
}

}  // namespace

std::uint32_t quantiseWith(Rounding r, double z) {
  if (std::isnan(z) || z <= 0.0)
    return 0;
  if (z >= 1.0)
    return 16777215u;
  const double x = z * kDepthMax;
  double q = 0.0;
  switch (r) {
    case Rounding::HalfUp:
      q = std::floor(x + 0.5);
      break;
    case Rounding::HalfAway:
      q = std::round(x);
      break;
    case Rounding::HalfDown:
      q = std::ceil(x - 0.5);
      break;
    case Rounding::Truncate:
      q = std::floor(x);
      break;
    case Rounding::Ceil:
      q = std::ceil(x);
      break;
    case Rounding::FloatMultiply:
      q = static_cast<double>(std::nearbyint(static_cast<float>(z) * 16777215.0f));
      break;
    case Rounding::ExactProduct:
      q = roundExactProduct(z);
      break;
    case Rounding::Scale2To24:
      q = std::nearbyint(z * 16777216.0);
      break;
    case Rounding::Scale2To24Truncate:
      q = std::floor(z * 16777216.0);
      break;
    default:
      q = std::nearbyint(x);
      break;
  }
  return std::min(16777215u, static_cast<std::uint32_t>(q));
}

}  // namespace recode::kit::detail
