#pragma once
// The depth plane's setup (docs/rasterization.md, section 5, up to the slopes) as a recipe
// (plane_recipe.hpp) computes it: the contract's separately rounded double operations, or a
// variant's other division, fusion or single precision.

#include "plane_recipe.hpp"

namespace recode::kit::detail {

// A triangle's snapped vertices and depths, in the order the plane is built from: the anchor
// first.
struct OrderedTriangle {
  long long X[3], Y[3];
  float Z[3];
};

struct PlaneSetup {
  double z0 = 0.0, dz1 = 0.0, dz2 = 0.0;
  double a2 = 0.0;            // the (double) twice-area the slopes divide by
  double na = 0.0, nb = 0.0;  // the slopes' numerators
  double dzdx = 0.0, dzdy = 0.0;
  // The same plane as floats, for an evaluation in float.
  float fz0 = 0.0f, fdzdx = 0.0f, fdzdy = 0.0f;
};

// v rounded to float and back. Through a volatile float: GCC 12 at -O2 vectorises two such
// round trips side by side (the two slopes) and then drops the rounding altogether, which
// would make the float readings give the contract's bits.
[[nodiscard]] inline double roundedToFloat(double v) {
  volatile float f = static_cast<float>(v);
  return static_cast<double>(f);
}

[[nodiscard]] PlaneSetup setUpPlane(const OrderedTriangle& t, const PlaneRecipe& recipe);

}  // namespace recode::kit::detail
