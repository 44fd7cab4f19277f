#pragma once
// The depth plane of the reference model (docs/rasterization.md, section 5) and its wrong
// variants, one triangle at a time: the contract's double-precision plane anchored at the first
// submitted vertex, or the way a variant sets it up and evaluates it.

#include <cstdint>
#include <vector>

#include "recode/kit/variants.hpp"

namespace recode::kit::detail {

class ModelPlane {
 public:
  // X, Y: snapped vertices in the submitted order; Z their floats; ccw the counter-clockwise
  // order of the vertices (0, 1, 2) or (0, 2, 1).
  ModelPlane(const long long X[3], const long long Y[3], const float Z[3], const int ccw[3],
             Variant variant);

  // The unquantised depth at the centre of pixel (i, j). Calls for one row in increasing i are
  // cheap under IncrementalFromPixel00, which steps from pixel (0, 0).
  [[nodiscard]] double at(int i, int j);

 private:
  void setUp(const long long X[3], const long long Y[3], const float Z[3], const int order[3]);
  [[nodiscard]] double contractAt(long long px, long long py) const;
  [[nodiscard]] double incrementalAt(int i, int j);

  Variant variant_;
  long long x0_ = 0, y0_ = 0;
  double z0_ = 0.0, dzdx_ = 0.0, dzdy_ = 0.0;
  float fz0_ = 0.0f, fdzdx_ = 0.0f, fdzdy_ = 0.0f;  // FloatPlane
  // IncrementalFromPixel00: row starts stepped from pixel (0, 0), and the last value given.
  std::vector<double> rowStart_;
  int lastI_ = -2, lastJ_ = -2;
  double lastZ_ = 0.0;
};

}  // namespace recode::kit::detail
