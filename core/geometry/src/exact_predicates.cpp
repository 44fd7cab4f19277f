// Exact orientation predicates: a double evaluation decides when its result exceeds a forward
// error bound; otherwise the determinant is evaluated exactly as a floating-point expansion.
//
// An expansion is a sum of doubles, kept non-overlapping and in increasing magnitude, with
// zeros removed, so that its sign is the sign of its last (largest) component. Two error-free
// transformations build it: two-sum (a + b = s + e exactly, Knuth) and two-product (a * b =
// p + e exactly, the error taken from a fused multiply-add). Adding one double into such an
// expansion, component by component with two-sum, keeps the properties (Shewchuk's
// Grow-Expansion theorem); sums and products are built from that step alone, which is slower
// than the tuned routines but simple to check, and the exact path runs only near degeneracy.

#include "recode/geometry/exact_predicates.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace recode::core {
namespace {

// s + e == a + b exactly, |e| <= ulp(s) / 2.
inline void twoSum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bVirtual = s - a;
  const double aVirtual = s - bVirtual;
  e = (a - aVirtual) + (b - bVirtual);
}

// p + e == a * b exactly (barring underflow): the fused multiply-add rounds once.
inline void twoProduct(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

// An expansion held on the stack: the exact paths below never need more components than the
// doubles summed into them, at most 192 (orient3d: three products of a two-component difference
// with a 16-component minor, each summing 2 x 16 two-products of two doubles). No allocation:
// the hull of a block with large coplanar faces takes this path for most of its tests.
class Expansion {
 public:
  static constexpr std::size_t kCapacity = 192;

  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  [[nodiscard]] double operator[](std::size_t i) const { return parts_[i]; }
  [[nodiscard]] double back() const { return parts_[size_ - 1]; }

  // this += b, keeping the components non-overlapping, increasing and free of zeros.
  void grow(double b) {
    double q = b;
    std::size_t out = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      double sum = 0.0;
      double err = 0.0;
      twoSum(q, parts_[i], sum, err);
      q = sum;
      if (err != 0.0)
        parts_[out++] = err;
    }
    if (q != 0.0) {
      if (out == kCapacity)
        throw std::logic_error("exact predicates: an expansion outgrew its capacity");
      parts_[out++] = q;
    }
    size_ = out;
  }

 private:
  std::array<double, kCapacity> parts_;
  std::size_t size_ = 0;
};

Expansion fromDifference(double a, double b) {
  Expansion e;
  e.grow(a);
  e.grow(-b);
  return e;
}

// e += sign * f (sign +1 or -1: exact).
void add(Expansion& e, const Expansion& f, double sign = 1.0) {
  for (std::size_t i = 0; i < f.size(); ++i)
    e.grow(sign * f[i]);
}

Expansion multiply(const Expansion& e, const Expansion& f) {
  Expansion product;
  for (std::size_t i = 0; i < e.size(); ++i) {
    for (std::size_t j = 0; j < f.size(); ++j) {
      double p = 0.0;
      double err = 0.0;
      twoProduct(e[i], f[j], p, err);
      product.grow(err);
      product.grow(p);
    }
  }
  return product;
}

int sign(const Expansion& e) {
  if (e.empty())
    return 0;
  return e.back() > 0.0 ? 1 : -1;
}

int signOf(double x) {
  return (x > 0.0) - (x < 0.0);
}

constexpr double kEpsilon = std::numeric_limits<double>::epsilon() / 2.0;  // 2^-53
// Forward error bounds of the double evaluations below, relative to the permanent (the same
// expression with every product's absolute value), as derived by Shewchuk for these exact
// formulas: each difference, product and sum adds one rounding.
constexpr double kOrient2dBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;

// (a0 - c0)(b1 - c1) - (a1 - c1)(b0 - c0), exactly.
int orient2dExact(double a0, double a1, double b0, double b1, double c0, double c1) {
  const Expansion acx = fromDifference(a0, c0);
  const Expansion acy = fromDifference(a1, c1);
  const Expansion bcx = fromDifference(b0, c0);
  const Expansion bcy = fromDifference(b1, c1);
  Expansion det = multiply(acx, bcy);
  add(det, multiply(acy, bcx), -1.0);
  return sign(det);
}

int orient3dExact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d) {
  const Expansion adx = fromDifference(a.x(), d.x());
  const Expansion ady = fromDifference(a.y(), d.y());
  const Expansion adz = fromDifference(a.z(), d.z());
  const Expansion bdx = fromDifference(b.x(), d.x());
  const Expansion bdy = fromDifference(b.y(), d.y());
  const Expansion bdz = fromDifference(b.z(), d.z());
  const Expansion cdx = fromDifference(c.x(), d.x());
  const Expansion cdy = fromDifference(c.y(), d.y());
  const Expansion cdz = fromDifference(c.z(), d.z());
  // Expansion along the first column: adx (bdy cdz - bdz cdy) + bdx (cdy adz - cdz ady)
  // + cdx (ady bdz - adz bdy).
  const auto minor = [](const Expansion& p, const Expansion& q, const Expansion& r,
                        const Expansion& s) {
    Expansion m = multiply(p, q);
    add(m, multiply(r, s), -1.0);
    return m;
  };
  Expansion det = multiply(adx, minor(bdy, cdz, bdz, cdy));
  add(det, multiply(bdx, minor(cdy, adz, cdz, ady)));
  add(det, multiply(cdx, minor(ady, bdz, adz, bdy)));
  return sign(det);
}

}  // namespace

int orient2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int i,
             int j) {
  const double left = (a[i] - c[i]) * (b[j] - c[j]);
  const double right = (a[j] - c[j]) * (b[i] - c[i]);
  const double det = left - right;
  const double bound = kOrient2dBound * (std::abs(left) + std::abs(right));
  if (std::abs(det) > bound)
    return signOf(det);
  return orient2dExact(a[i], a[j], b[i], b[j], c[i], c[j]);
}

bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return orient2d(a, b, c, 0, 1) == 0 && orient2d(a, b, c, 1, 2) == 0 &&
         orient2d(a, b, c, 2, 0) == 0;
}

int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d) {
  const double adx = a.x() - d.x();
  const double ady = a.y() - d.y();
  const double adz = a.z() - d.z();
  const double bdx = b.x() - d.x();
  const double bdy = b.y() - d.y();
  const double bdz = b.z() - d.z();
  const double cdx = c.x() - d.x();
  const double cdy = c.y() - d.y();
  const double cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy;
  const double cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady;
  const double adxcdy = adx * cdy;
  const double adxbdy = adx * bdy;
  const double bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  if (std::abs(det) > kOrient3dBound * permanent)
    return signOf(det);
  return orient3dExact(a, b, c, d);
}

}  // namespace recode::core
