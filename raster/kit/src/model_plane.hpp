#pragma once
// The depth plane of the reference model (docs/rasterization.md, section 5) and its wrong
// variants, one triangle at a time: the contract's double-precision plane anchored at the first
// submitted vertex, or the way a variant's recipe (plane_recipe.hpp) anchors, sets up and
// evaluates it.

#include <vector>

#include "model_plane_setup.hpp"
#include "recode/kit/variants.hpp"

namespace recode::kit::detail {

class ModelPlane {
 public:
  // X, Y: snapped vertices in the submitted order; Z their floats; ccw the counter-clockwise
  // order of the vertices (0, 1, 2) or (0, 2, 1).
  ModelPlane(const long long X[3], const long long Y[3], const float Z[3], const int ccw[3],
             Variant variant);

  // The unquantised depth at the centre of pixel (i, j). Calls for one row in increasing i are
  // cheap when the recipe steps from pixel (0, 0).
  [[nodiscard]] double at(int i, int j);

 private:
  // The plane's value at (px, py) the way the recipe evaluates it from (x0_, y0_).
  [[nodiscard]] double evaluate(long long px, long long py) const;
  [[nodiscard]] double barycentricAt(long long px, long long py) const;
  [[nodiscard]] double incrementalAt(int i, int j);

  PlaneRecipe recipe_;
  OrderedTriangle tri_;  // anchor first
  PlaneSetup plane_;
  long long x0_ = 0, y0_ = 0;  // where the evaluation starts: the anchor or the point carried to
  // SteppedFromPixel00: row starts stepped from pixel (0, 0), and the last value given.
  std::vector<double> rowStart_;
  int lastI_ = -2, lastJ_ = -2;
  double lastZ_ = 0.0;
};

}  // namespace recode::kit::detail
