// GJK on the Minkowski difference A - B. The closest point of each simplex (at most four
// points) to the origin is found by trying every face of it: the affine minimiser of each
// subset, kept when its barycentric weights are all non-negative; the nearest kept point is
// the simplex's closest point and its subset the next simplex. With at most 15 subsets this
// is cheap, and it has none of the case analysis that makes hand-written sub-algorithms
// fragile.
#include "recode/geometry/convex_distance.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

namespace {

// The first of every `stride`-th point (from the first) furthest along d.
Eigen::Vector3d furthest(std::span<const Eigen::Vector3d> points, const Eigen::Vector3d& d,
                         std::size_t stride = 1) {
  const Eigen::Vector3d* best = &points[0];
  double bestDot = best->dot(d);
  for (std::size_t i = stride; i < points.size(); i += stride) {
    const double dot = points[i].dot(d);
    if (dot > bestDot) {
      bestDot = dot;
      best = &points[i];
    }
  }
  return *best;
}

struct Closest {
  Eigen::Vector3d point;
  std::vector<Eigen::Vector3d> simplex;  // the subset whose face holds the point
};

// The point of conv(simplex) nearest the origin.
Closest closestOnSimplex(const std::vector<Eigen::Vector3d>& simplex) {
  const int n = static_cast<int>(simplex.size());
  Closest best;
  double bestNorm = std::numeric_limits<double>::infinity();
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<Eigen::Vector3d> subset;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i))
        subset.push_back(simplex[static_cast<std::size_t>(i)]);
    const int m = static_cast<int>(subset.size());
    // Minimise |p0 + sum_i t_i (p_i - p0)|: normal equations G t = -E^T p0.
    Eigen::VectorXd weights(m);
    if (m == 1) {
      weights(0) = 1.0;
    } else {
      Eigen::MatrixXd e(3, m - 1);
      for (int i = 1; i < m; ++i)
        e.col(i - 1) = subset[static_cast<std::size_t>(i)] - subset[0];
      const Eigen::MatrixXd g = e.transpose() * e;
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(g);
      if (lu.rank() < m - 1)
        continue;  // a degenerate face: its points are covered by smaller subsets
      const Eigen::VectorXd t = lu.solve(-e.transpose() * subset[0]);
      weights(0) = 1.0 - t.sum();
      weights.tail(m - 1) = t;
    }
    if ((weights.array() < -1e-12).any())
      continue;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < m; ++i)
      p += weights(i) * subset[static_cast<std::size_t>(i)];
    const double norm = p.norm();
    // Prefer the smaller subset on a tie, so the simplex stays small.
    if (norm < bestNorm * (1.0 - 1e-14) ||
        (norm <= bestNorm && subset.size() < best.simplex.size())) {
      bestNorm = norm;
      best.point = p;
      best.simplex = subset;
    }
  }
  return best;
}

// The same point by the same subsets and tests, in fixed-size storage: no allocation per subset
// or solve, for the skip-apart test, which runs GJK for every pair of a frame. The rounding of
// its solves may differ from the one above in the last places, which changes no proof (the slab
// checked on every point carries it); closestOnSimplex above stays as it is because the hand
// scene's poses are made with convexHullDistance.
template <int K>
bool affineWeights(const std::array<const Eigen::Vector3d*, 4>& subset, double* weights) {
  Eigen::Matrix<double, 3, K> e;
  for (int i = 1; i <= K; ++i)
    e.col(i - 1) = *subset[static_cast<std::size_t>(i)] - *subset[0];
  const Eigen::Matrix<double, K, K> g = e.transpose() * e;
  const Eigen::FullPivLU<Eigen::Matrix<double, K, K>> lu(g);
  if (lu.rank() < K)
    return false;
  const Eigen::Matrix<double, K, 1> t = lu.solve(-e.transpose() * *subset[0]);
  weights[0] = 1.0 - t.sum();
  for (int i = 0; i < K; ++i)
    weights[i + 1] = t(i);
  return true;
}

Closest closestOnSimplexFixed(const std::vector<Eigen::Vector3d>& simplex) {
  const int n = static_cast<int>(simplex.size());
  Closest best;
  int bestMask = 0, bestSize = 0;
  double bestNorm = std::numeric_limits<double>::infinity();
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::array<const Eigen::Vector3d*, 4> subset{};
    int m = 0;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i))
        subset[static_cast<std::size_t>(m++)] = &simplex[static_cast<std::size_t>(i)];
    double weights[4] = {1.0, 0.0, 0.0, 0.0};
    const bool solved = m == 1   ? true
                        : m == 2 ? affineWeights<1>(subset, weights)
                        : m == 3 ? affineWeights<2>(subset, weights)
                                 : affineWeights<3>(subset, weights);
    if (!solved)
      continue;  // a degenerate face: its points are covered by smaller subsets
    if (std::any_of(weights, weights + m, [](double w) { return w < -1e-12; }))
      continue;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < m; ++i)
      p += weights[i] * *subset[static_cast<std::size_t>(i)];
    const double norm = p.norm();
    if (norm < bestNorm * (1.0 - 1e-14) || (norm <= bestNorm && m < bestSize)) {
      bestNorm = norm;
      best.point = p;
      bestMask = mask;
      bestSize = m;
    }
  }
  for (int i = 0; i < n; ++i)
    if (bestMask & (1 << i))
      best.simplex.push_back(simplex[static_cast<std::size_t>(i)]);
  return best;
}

// The rounding threshold of both answers, relative to the points' largest coordinate: a
// thousand times the rounding of a dot product, far below any pixel.
constexpr double kRelativeTolerance = 1e-12;

// GJK's answer: the distance (an upper bound within rounding: the length of a point of
// conv(A - B)) and that point, the direction from B towards A; zero when they intersect.
// tiny is kRelativeTolerance of the points' largest coordinate.
struct Approach {
  double distance = 0.0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double tiny = 0.0;
};

// GJK on conv(A) - conv(B), each given by its support function (the point furthest along a
// direction), from `start`, a point of A - B; `scale` sets the rounding threshold.
template <typename SupportA, typename SupportB>
Approach closestApproach(
    const SupportA& furthestA, const SupportB& furthestB, const Eigen::Vector3d& start,
    double scale, Closest (*closestOn)(const std::vector<Eigen::Vector3d>&) = closestOnSimplex) {
  const double tiny = kRelativeTolerance * std::max(scale, 1e-300);

  // v is always the point of conv(simplex) nearest the origin, so a new simplex can only
  // bring it nearer.
  Eigen::Vector3d v = start;
  std::vector<Eigen::Vector3d> simplex{v};
  const auto apart = [&] { return Approach{v.norm(), v, tiny}; };
  const Approach touching{0.0, Eigen::Vector3d::Zero(), tiny};
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double vv = v.norm();
    if (vv <= tiny)
      return touching;
    const Eigen::Vector3d w = furthestA(-v) - furthestB(v);
    // No point of A - B lies nearer the origin along v than v itself (to rounding): done.
    if (vv * vv - v.dot(w) <= kRelativeTolerance * vv * vv)
      return apart();
    if (std::find(simplex.begin(), simplex.end(), w) != simplex.end())
      return apart();
    simplex.push_back(w);
    const Closest c = closestOn(simplex);
    if (c.simplex.empty())
      return apart();  // numerically stuck; v is the best found
    if (c.simplex.size() == 4)
      return touching;  // the origin lies inside the tetrahedron
    if (c.point.norm() >= vv)
      return apart();  // no progress
    v = c.point;
    simplex = c.simplex;
  }
  return apart();
}

// A point set as GJK and the slab read it: its world points as they are.
class WorldSet {
 public:
  explicit WorldSet(std::span<const Eigen::Vector3d> points) : points_(points) {}
  [[nodiscard]] std::size_t size() const { return points_.size(); }
  [[nodiscard]] Eigen::Vector3d first() const { return points_[0]; }
  [[nodiscard]] Eigen::Vector3d furthest(const Eigen::Vector3d& d, std::size_t stride) const {
    return core::furthest(points_, d, stride);
  }
  // The least and the greatest n.p over every point.
  [[nodiscard]] double lowest(const Eigen::Vector3d& n) const {
    double low = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : points_)
      low = std::min(low, p.dot(n));
    return low;
  }
  [[nodiscard]] double highest(const Eigen::Vector3d& n) const { return -lowest(-n); }
  [[nodiscard]] double largestCoordinate() const {
    double scale = 0.0;
    for (const Eigen::Vector3d& p : points_)
      scale = std::max(scale, p.cwiseAbs().maxCoeff());
    return scale;
  }

 private:
  std::span<const Eigen::Vector3d> points_;
};

Approach closestApproach(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b) {
  if (a.empty() || b.empty())
    throw std::invalid_argument("convexHullDistance: an empty point set");
  const double scale = std::max(WorldSet(a).largestCoordinate(), WorldSet(b).largestCoordinate());
  return closestApproach([a](const Eigen::Vector3d& d) { return furthest(a, d); },
                         [b](const Eigen::Vector3d& d) { return furthest(b, d); }, a[0] - b[0],
                         scale);
}

// The same for a set read in its own coordinates: a support is made as its world point is
// (posedPoint, transformed()'s arithmetic); a slab end is (L^T n).p + n.t, within about 1e-15 of
// the world points' size of the world value.
class PosedSet {
 public:
  explicit PosedSet(const PosedPoints& points)
      : local_(points.local),
        linear_(points.pose.linear()),
        transposed_(linear_.transpose()),
        translation_(points.pose.translation()),
        pose_(rasterPose(linear_, translation_)) {}
  [[nodiscard]] std::size_t size() const { return local_.size(); }
  [[nodiscard]] Eigen::Vector3d first() const { return world(local_[0]); }
  [[nodiscard]] Eigen::Vector3d furthest(const Eigen::Vector3d& d, std::size_t stride) const {
    return world(core::furthest(local_, Eigen::Vector3d(transposed_ * d), stride));
  }
  [[nodiscard]] double lowest(const Eigen::Vector3d& n) const {
    return WorldSet(local_).lowest(transposed_ * n) + translation_.dot(n);
  }
  [[nodiscard]] double highest(const Eigen::Vector3d& n) const {
    return WorldSet(local_).highest(transposed_ * n) + translation_.dot(n);
  }
  // A bound of every world coordinate: |L p + t| <= ||L||_inf |p|_inf + |t|_inf per axis.
  [[nodiscard]] double largestCoordinate() const {
    const double rows = linear_.cwiseAbs().rowwise().sum().maxCoeff();
    return rows * WorldSet(local_).largestCoordinate() + translation_.cwiseAbs().maxCoeff();
  }

 private:
  [[nodiscard]] Eigen::Vector3d world(const Eigen::Vector3d& p) const {
    return posedPoint(pose_, p);
  }
  std::span<const Eigen::Vector3d> local_;
  Eigen::Matrix3d linear_, transposed_;
  Eigen::Vector3d translation_;
  raster::Pose pose_;  // linear_ and translation_ as posedPoint takes them, made once
};

// The width of the empty slab across unit direction n between conv(a) grown by the box
// [-margin, margin] (lower side) and conv(b) (upper side), each end checked against every point.
template <typename SetA, typename SetB>
double slabWidth(const SetA& a, const SetB& b, const Eigen::Vector3d& n,
                 const Eigen::Vector3d& margin) {
  return a.lowest(n) - margin.dot(n.cwiseAbs()) - b.highest(n);
}

// GJK between conv(a) grown by the box and conv(b), each point set read every `stride`-th
// point; then the slab across its direction, checked against every point.
template <typename SetA, typename SetB>
bool slabBeyondFound(const SetA& a, const SetB& b, const Eigen::Vector3d& margin, double scale,
                     std::size_t strideA, std::size_t strideB) {
  // conv(a) grown by the box: its support is a's plus the box corner the direction points to.
  const auto furthestGrownA = [&a, &margin, strideA](const Eigen::Vector3d& d) {
    const Eigen::Vector3d corner(d.x() >= 0.0 ? margin.x() : -margin.x(),
                                 d.y() >= 0.0 ? margin.y() : -margin.y(),
                                 d.z() >= 0.0 ? margin.z() : -margin.z());
    return Eigen::Vector3d(a.furthest(d, strideA) + corner);
  };
  const Approach approach = closestApproach(
      furthestGrownA, [&b, strideB](const Eigen::Vector3d& d) { return b.furthest(d, strideB); },
      Eigen::Vector3d(a.first() + margin - b.first()), scale, closestOnSimplexFixed);
  if (approach.distance == 0.0)
    return false;
  const Eigen::Vector3d n = approach.direction / approach.distance;
  return slabWidth(a, b, n, margin) > approach.tiny;
}

// Points GJK reads a side before it reads them all.
constexpr std::size_t kSampledPoints = 64;

}  // namespace

double convexHullDistance(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b) {
  return closestApproach(a, b).distance;
}

double convexHullGap(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b) {
  const Approach approach = closestApproach(a, b);
  if (approach.distance == 0.0)
    return 0.0;
  // The empty slab between the point sets across GJK's direction: every point of A is at
  // least lowA along it and every point of B at most highB.
  const Eigen::Vector3d n = approach.direction / approach.distance;
  const double width = slabWidth(WorldSet(a), WorldSet(b), n, Eigen::Vector3d::Zero());
  // A slab no wider than the rounding of its ends is no proof.
  return width > approach.tiny ? width : 0.0;
}

namespace {

void checkMargin(const Eigen::Vector3d& margin) {
  if (!(margin.array() >= 0.0).all() || !margin.allFinite())
    throw std::invalid_argument("hullsApartBeyond: the margin must be finite and non-negative");
}

template <typename SetA, typename SetB>
bool apartBeyond(const SetA& a, const SetB& b, const Eigen::Vector3d& margin) {
  if (a.size() == 0 || b.size() == 0)
    throw std::invalid_argument("hullsApartBeyond: an empty point set");
  const double scale = std::max(a.largestCoordinate(), b.largestCoordinate()) + margin.maxCoeff();
  // GJK's direction from a sample of each set is most often good enough, at a fraction of the
  // reads; whichever direction is used, the proof is the slab checked on every point.
  const std::size_t strideA = std::max<std::size_t>(1, a.size() / kSampledPoints);
  const std::size_t strideB = std::max<std::size_t>(1, b.size() / kSampledPoints);
  if ((strideA > 1 || strideB > 1) && slabBeyondFound(a, b, margin, scale, strideA, strideB))
    return true;
  return slabBeyondFound(a, b, margin, scale, 1, 1);
}

}  // namespace

bool hullsApartBeyond(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b,
                      const Eigen::Vector3d& margin) {
  checkMargin(margin);
  return apartBeyond(WorldSet(a), WorldSet(b), margin);
}

bool hullsApartBeyond(const PosedPoints& a, const PosedPoints& b, const Eigen::Vector3d& margin) {
  checkMargin(margin);
  return apartBeyond(PosedSet(a), PosedSet(b), margin);
}

}  // namespace recode::core
