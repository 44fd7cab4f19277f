#include "model_plane_setup.hpp"

#include <cmath>

namespace recode::kit::detail {

namespace {

// p q - r s, each product rounded on its own unless one is fused into the subtraction.
double difference(double p, double q, double r, double s, bool fuseLeft, bool fuseRight) {
  if (fuseLeft)
    return std::fma(p, q, -(r * s));
  if (fuseRight)
    return std::fma(-r, s, p * q);
  return p * q - r * s;
}

// (p q - r s) / a2, with n = p q - r s already rounded, the way `form` places the division.
double slope(SlopeForm form, double p, double q, double r, double s, double n, double a2) {
  const double inv = 1.0 / a2;
  switch (form) {
    case SlopeForm::DivideTerms:
      return (p * q) / a2 - (r * s) / a2;
    case SlopeForm::EdgeOverArea:
      return p * (q / a2) - r * (s / a2);
    case SlopeForm::DepthOverArea:
      return (p / a2) * q - (r / a2) * s;
    case SlopeForm::Reciprocal:
      return n * inv;
    case SlopeForm::ReciprocalTerms:
      return (p * q) * inv - (r * s) * inv;
    case SlopeForm::EdgeTimesReciprocal:
      return p * (q * inv) - r * (s * inv);
    case SlopeForm::DepthTimesReciprocal:
      return (p * inv) * q - (r * inv) * s;
    default:
      return n / a2;
  }
}

// The whole setup in float, as a back end written in float does it: the area is the exact
// integer rounded once (the edge differences are exact in float: at most 2^24).
void setUpInFloat(const OrderedTriangle& t, long long area, PlaneSetup& s) {
  const float dz1 = t.Z[1] - t.Z[0], dz2 = t.Z[2] - t.Z[0];
  const float ex1 = static_cast<float>(t.X[1] - t.X[0]), ey1 = static_cast<float>(t.Y[1] - t.Y[0]);
  const float ex2 = static_cast<float>(t.X[2] - t.X[0]), ey2 = static_cast<float>(t.Y[2] - t.Y[0]);
  const float a2 = static_cast<float>(area);
  s.fz0 = t.Z[0];
  s.fdzdx = (dz1 * ey2 - dz2 * ey1) / a2;
  s.fdzdy = (dz2 * ex1 - dz1 * ex2) / a2;
  s.z0 = static_cast<double>(s.fz0);
  s.dzdx = static_cast<double>(s.fdzdx);
  s.dzdy = static_cast<double>(s.fdzdy);
}

}  // namespace

PlaneSetup setUpPlane(const OrderedTriangle& t, const PlaneRecipe& recipe) {
  const long long area =
      (t.X[1] - t.X[0]) * (t.Y[2] - t.Y[0]) - (t.X[2] - t.X[0]) * (t.Y[1] - t.Y[0]);
  PlaneSetup s;
  if (recipe.inFloat & kFloatSetup) {
    setUpInFloat(t, area, s);
    return s;
  }
  s.z0 = static_cast<double>(t.Z[0]);
  if (recipe.inFloat & kFloatDepthInputs) {
    s.dz1 = static_cast<double>(t.Z[1] - t.Z[0]);
    s.dz2 = static_cast<double>(t.Z[2] - t.Z[0]);
  } else {
    s.dz1 = static_cast<double>(t.Z[1]) - s.z0;
    s.dz2 = static_cast<double>(t.Z[2]) - s.z0;
  }
  // The integer differences are exact in double (and in float: at most 2^24).
  const double ex1 = static_cast<double>(t.X[1] - t.X[0]),
               ey1 = static_cast<double>(t.Y[1] - t.Y[0]);
  const double ex2 = static_cast<double>(t.X[2] - t.X[0]),
               ey2 = static_cast<double>(t.Y[2] - t.Y[0]);
  if (recipe.inFloat & kFloatArea) {
    const float fx1 = static_cast<float>(ex1), fy1 = static_cast<float>(ey1);
    const float fx2 = static_cast<float>(ex2), fy2 = static_cast<float>(ey2);
    s.a2 = static_cast<double>(fx1 * fy2 - fx2 * fy1);
  } else {
    s.a2 = static_cast<double>(area);  // below 2^49: exact
  }
  s.na = difference(s.dz1, ey2, s.dz2, ey1, recipe.fused & kFuseSlopeXLeft,
                    recipe.fused & kFuseSlopeXRight);
  s.nb = difference(s.dz2, ex1, s.dz1, ex2, recipe.fused & kFuseSlopeYLeft,
                    recipe.fused & kFuseSlopeYRight);
  s.dzdx = slope(recipe.slopes, s.dz1, ey2, s.dz2, ey1, s.na, s.a2);
  s.dzdy = slope(recipe.slopes, s.dz2, ex1, s.dz1, ex2, s.nb, s.a2);
  s.fz0 = t.Z[0];
  s.fdzdx = static_cast<float>(s.dzdx);
  s.fdzdy = static_cast<float>(s.dzdy);
  if (recipe.inFloat & kFloatStoredSlopes) {
    s.dzdx = roundedToFloat(s.dzdx);
    s.dzdy = roundedToFloat(s.dzdy);
  }
  return s;
}

}  // namespace recode::kit::detail
