#include "model_plane.hpp"

#include <cmath>

namespace recode::kit::detail {

namespace {

long long centre(int i) {
  return 256LL * i + 128;
}

}  // namespace

ModelPlane::ModelPlane(const long long X[3], const long long Y[3], const float Z[3],
                       const int ccw[3], Variant variant)
    : variant_(variant) {
  int order[3] = {0, 1, 2};
  if (variant == Variant::AnchorRotated) {
    order[0] = 1, order[1] = 2, order[2] = 0;
  } else if (variant == Variant::AnchorSorted) {
    // A rasterizer that sorts: counter-clockwise, starting at the lowest vertex (y, then x).
    int first = 0;
    for (int k = 1; k < 3; ++k) {
      const int c = ccw[k], f = ccw[first];
      if (Y[c] < Y[f] || (Y[c] == Y[f] && X[c] < X[f]))
        first = k;
    }
    for (int k = 0; k < 3; ++k)
      order[k] = ccw[(first + k) % 3];
  }
  setUp(X, Y, Z, order);
}

void ModelPlane::setUp(const long long X[3], const long long Y[3], const float Z[3],
                       const int order[3]) {
  const int a = order[0], b = order[1], c = order[2];
  x0_ = X[a];
  y0_ = Y[a];
  const long long area = (X[b] - X[a]) * (Y[c] - Y[a]) - (X[c] - X[a]) * (Y[b] - Y[a]);
  if (variant_ == Variant::FloatPlane) {
    const float dz1 = Z[b] - Z[a], dz2 = Z[c] - Z[a];
    const float ex1 = static_cast<float>(X[b] - X[a]), ey1 = static_cast<float>(Y[b] - Y[a]);
    const float ex2 = static_cast<float>(X[c] - X[a]), ey2 = static_cast<float>(Y[c] - Y[a]);
    const float a2 = static_cast<float>(area);
    fz0_ = Z[a];
    fdzdx_ = (dz1 * ey2 - dz2 * ey1) / a2;
    fdzdy_ = (dz2 * ex1 - dz1 * ex2) / a2;
    return;
  }
  z0_ = static_cast<double>(Z[a]);
  const double dz1 = static_cast<double>(Z[b]) - z0_, dz2 = static_cast<double>(Z[c]) - z0_;
  const double ex1 = static_cast<double>(X[b] - X[a]), ey1 = static_cast<double>(Y[b] - Y[a]);
  const double ex2 = static_cast<double>(X[c] - X[a]), ey2 = static_cast<double>(Y[c] - Y[a]);
  const double a2 = static_cast<double>(area);
  if (variant_ == Variant::FmaPlane) {
    dzdx_ = std::fma(dz1, ey2, -(dz2 * ey1)) / a2;
    dzdy_ = std::fma(dz2, ex1, -(dz1 * ex2)) / a2;
  } else {
    dzdx_ = (dz1 * ey2 - dz2 * ey1) / a2;
    dzdy_ = (dz2 * ex1 - dz1 * ex2) / a2;
  }
}

double ModelPlane::contractAt(long long px, long long py) const {
  return (z0_ + dzdx_ * static_cast<double>(px - x0_)) + dzdy_ * static_cast<double>(py - y0_);
}

double ModelPlane::incrementalAt(int i, int j) {
  if (j == lastJ_ && i == lastI_ + 1) {
    lastZ_ += dzdx_ * 256.0;
  } else {
    while (static_cast<int>(rowStart_.size()) <= j) {
      rowStart_.push_back(rowStart_.empty() ? contractAt(centre(0), centre(0))
                                            : rowStart_.back() + dzdy_ * 256.0);
    }
    lastZ_ = rowStart_[static_cast<std::size_t>(j)];
    for (int k = 0; k < i; ++k)
      lastZ_ += dzdx_ * 256.0;
  }
  lastI_ = i;
  lastJ_ = j;
  return lastZ_;
}

double ModelPlane::at(int i, int j) {
  const long long px = centre(i), py = centre(j);
  switch (variant_) {
    case Variant::FloatPlane:
      return static_cast<double>((fz0_ + fdzdx_ * static_cast<float>(px - x0_)) +
                                 fdzdy_ * static_cast<float>(py - y0_));
    case Variant::FmaPlane:
      return std::fma(dzdy_, static_cast<double>(py - y0_),
                      std::fma(dzdx_, static_cast<double>(px - x0_), z0_));
    case Variant::PlaneFromOrigin: {
      const double c = (z0_ - dzdx_ * static_cast<double>(x0_)) - dzdy_ * static_cast<double>(y0_);
      return (c + dzdx_ * static_cast<double>(px)) + dzdy_ * static_cast<double>(py);
    }
    case Variant::IncrementalFromPixel00:
      return incrementalAt(i, j);
    default:
      return contractAt(px, py);
  }
}

}  // namespace recode::kit::detail
