#include "model_plane.hpp"

#include <cmath>

namespace recode::kit::detail {

namespace {

long long centre(long long i) {
  return 256 * i + 128;
}

// The order (anchor first, the others following cyclically in submitted order or, for a
// rasterizer that sorts, counter-clockwise) the recipe builds the plane from. Which of the
// other two comes first does not change the bits (section 5), only the anchor does.
void planeOrder(AnchorVertex anchor, const long long X[3], const long long Y[3], const int ccw[3],
                int order[3]) {
  int first = 0;
  switch (anchor) {
    case AnchorVertex::Second:
      first = 1;
      break;
    case AnchorVertex::Third:
      first = 2;
      break;
    case AnchorVertex::Lowest:
    case AnchorVertex::Highest:
      for (int k = 1; k < 3; ++k) {
        const int c = ccw[k], f = ccw[first];
        const bool lower = Y[c] < Y[f] || (Y[c] == Y[f] && X[c] < X[f]);
        const bool higher = Y[c] > Y[f] || (Y[c] == Y[f] && X[c] < X[f]);
        if (anchor == AnchorVertex::Lowest ? lower : higher)
          first = k;
      }
      for (int k = 0; k < 3; ++k)
        order[k] = ccw[(first + k) % 3];
      return;
    default:
      break;
  }
  for (int k = 0; k < 3; ++k)
    order[k] = (first + k) % 3;
}

// The centre of the pixel column (or row) that holds the fixed-point coordinate v: v / 256
// rounded down, also for negative v.
long long pixelCentreOf(long long v) {
  const long long pixel = v >= 0 ? v / 256 : -((-v + 255) / 256);
  return centre(pixel);
}

}  // namespace

ModelPlane::ModelPlane(const long long X[3], const long long Y[3], const float Z[3],
                       const int ccw[3], Variant variant)
    : recipe_(planeRecipe(variant)) {
  int order[3];
  planeOrder(recipe_.anchor, X, Y, ccw, order);
  for (int k = 0; k < 3; ++k) {
    tri_.X[k] = X[order[k]];
    tri_.Y[k] = Y[order[k]];
    tri_.Z[k] = Z[order[k]];
  }
  plane_ = setUpPlane(tri_, recipe_);
  x0_ = tri_.X[0];
  y0_ = tri_.Y[0];
  // A recipe that starts elsewhere carries the plane there first, evaluated as the contract
  // does, and takes that value as its z0.
  long long rx = 0, ry = 0;
  switch (recipe_.origin) {
    case PlaneOrigin::AnchorPixelCentre:
      rx = pixelCentreOf(x0_), ry = pixelCentreOf(y0_);
      break;
    case PlaneOrigin::Pixel00:
      rx = centre(0), ry = centre(0);
      break;
    case PlaneOrigin::FramebufferOrigin:
      break;
    default:
      return;
  }
  plane_.z0 = evaluate(rx, ry);
  x0_ = rx;
  y0_ = ry;
}

double ModelPlane::evaluate(long long px, long long py) const {
  const PlaneSetup& p = plane_;
  const double dx = static_cast<double>(px - x0_), dy = static_cast<double>(py - y0_);
  if (recipe_.inFloat & kFloatEvaluation) {
    // |dx|, |dy| < 2^24: exact in float too.
    return static_cast<double>((p.fz0 + p.fdzdx * static_cast<float>(dx)) +
                               p.fdzdy * static_cast<float>(dy));
  }
  switch (recipe_.eval) {
    case EvalForm::YThenX:
      return (p.z0 + p.dzdy * dy) + p.dzdx * dx;
    case EvalForm::OffsetsFirst:
      return p.z0 + (p.dzdx * dx + p.dzdy * dy);
    case EvalForm::DivideSum:
      return p.z0 + (p.na * dx + p.nb * dy) / p.a2;
    case EvalForm::DivideTerms:
      return (p.z0 + (p.na * dx) / p.a2) + (p.nb * dy) / p.a2;
    case EvalForm::OffsetsOverArea:
      return (p.z0 + p.na * (dx / p.a2)) + p.nb * (dy / p.a2);
    case EvalForm::Barycentric:
    case EvalForm::BarycentricWeights:
      return barycentricAt(px, py);
    default:
      break;
  }
  const double sx = (recipe_.fused & kFuseEvalX) ? std::fma(p.dzdx, dx, p.z0) : p.z0 + p.dzdx * dx;
  return (recipe_.fused & kFuseEvalY) ? std::fma(p.dzdy, dy, sx) : sx + p.dzdy * dy;
}

double ModelPlane::barycentricAt(long long px, long long py) const {
  const OrderedTriangle& t = tri_;
  const long long e1x = t.X[1] - t.X[0], e1y = t.Y[1] - t.Y[0];
  const long long e2x = t.X[2] - t.X[0], e2y = t.Y[2] - t.Y[0];
  const long long dx = px - t.X[0], dy = py - t.Y[0];
  // The edge functions opposite v1 and v2 and the area: exact in 64 bits (below 2^50).
  const long long area = e1x * e2y - e2x * e1y;
  const long long w1 = e2y * dx - e2x * dy, w2 = e1x * dy - e1y * dx;
  const double a2 = static_cast<double>(area);
  const double l1 = static_cast<double>(w1) / a2, l2 = static_cast<double>(w2) / a2;
  if (recipe_.eval == EvalForm::Barycentric)
    return (plane_.z0 + l1 * plane_.dz1) + l2 * plane_.dz2;
  const double l0 = static_cast<double>(area - w1 - w2) / a2;
  return (l0 * static_cast<double>(t.Z[0]) + l1 * static_cast<double>(t.Z[1])) +
         l2 * static_cast<double>(t.Z[2]);
}

double ModelPlane::incrementalAt(int i, int j) {
  const PlaneSetup& p = plane_;
  if (j == lastJ_ && i == lastI_ + 1) {
    lastZ_ += p.dzdx * 256.0;
  } else {
    while (static_cast<int>(rowStart_.size()) <= j) {
      rowStart_.push_back(rowStart_.empty() ? evaluate(centre(0), centre(0))
                                            : rowStart_.back() + p.dzdy * 256.0);
    }
    lastZ_ = rowStart_[static_cast<std::size_t>(j)];
    for (int k = 0; k < i; ++k)
      lastZ_ += p.dzdx * 256.0;
  }
  lastI_ = i;
  lastJ_ = j;
  return lastZ_;
}

double ModelPlane::at(int i, int j) {
  const double z = recipe_.origin == PlaneOrigin::SteppedFromPixel00
                       ? incrementalAt(i, j)
                       : evaluate(centre(i), centre(j));
  return (recipe_.inFloat & kFloatOutput) ? roundedToFloat(z) : z;
}

}  // namespace recode::kit::detail
