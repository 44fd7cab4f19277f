#include "recode/pair/contact_normal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>

namespace recode::core {

namespace {

// Directions over the half sphere z >= 0 on a Fibonacci spiral: nearly even spacing (about 9
// degrees apart for 256), so the local refinement starts near every basin of the width.
constexpr int kSpiralDirections = 256;
// The refinement starts from this many of the best seeds (the width over the sphere can have
// several shallow basins, e.g. a square overlap has two equally thin sides).
constexpr int kRefinedSeeds = 4;
constexpr double kFirstStepRad = 6.0 * std::numbers::pi / 180.0;
constexpr double kLastStepRad = 0.005 * std::numbers::pi / 180.0;

// Normal of the least-squares plane through every `stride`-th end starting at `first` (the
// direction of least spread about their centroid); zero with fewer than three points.
Eigen::Vector3d planeNormal(std::span<const Eigen::Vector3d> ends, std::size_t first) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (std::size_t i = first; i < ends.size(); i += 2, ++n)
    mean += ends[i];
  if (n < 3)
    return Eigen::Vector3d::Zero();
  mean /= static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (std::size_t i = first; i < ends.size(); i += 2) {
    const Eigen::Vector3d q = ends[i] - mean;
    scatter += q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  return solver.eigenvectors().col(0);  // eigenvalues ascending
}

struct Candidate {
  Eigen::Vector3d direction;
  double width = 0.0;
};

// Pattern search on the sphere: the eight neighbours at the current step along two tangent
// directions; move to the best one that is thinner, else halve the step.
Candidate refine(const OverlapSamples& samples, Candidate best) {
  double step = kFirstStepRad;
  while (step > kLastStepRad) {
    const Eigen::Vector3d& d = best.direction;
    const Eigen::Vector3d helper =
        std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d t1 = d.cross(helper).normalized();
    const Eigen::Vector3d t2 = d.cross(t1);
    Candidate next = best;
    for (int i = -1; i <= 1; ++i) {
      for (int j = -1; j <= 1; ++j) {
        if (i == 0 && j == 0)
          continue;
        const Eigen::Vector3d e =
            (d + std::tan(step) * (static_cast<double>(i) * t1 + static_cast<double>(j) * t2))
                .normalized();
        const double w = overlapWidth(samples, e);
        if (w < next.width)
          next = {e, w};
      }
    }
    if (next.width < best.width)
      best = next;
    else
      step /= 2.0;
  }
  return best;
}

double support(std::span<const Eigen::Vector3d> vertices, const Eigen::Vector3d& d) {
  double s = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& v : vertices)
    s = std::max(s, v.dot(d));
  return s;
}

}  // namespace

double overlapWidth(const OverlapSamples& samples, const Eigen::Vector3d& d) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Eigen::Vector3d& p : samples.ends) {
    const double s = p.dot(d);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return hi - lo + 2.0 * samples.halfPixel.dot(d.cwiseAbs());
}

Eigen::Vector3d thinnestDirection(const OverlapSamples& samples) {
  std::vector<Candidate> seeds;
  seeds.reserve(kSpiralDirections + 5);
  const auto add = [&](const Eigen::Vector3d& d) {
    if (d.squaredNorm() > 0.0)
      seeds.push_back({d.normalized(), overlapWidth(samples, d.normalized())});
  };
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kSpiralDirections; ++i) {
    const double z = (i + 0.5) / kSpiralDirections;
    const double r = std::sqrt(1.0 - z * z);
    add({r * std::cos(golden * i), r * std::sin(golden * i), z});
  }
  add(Eigen::Vector3d::UnitX());
  add(Eigen::Vector3d::UnitY());
  add(Eigen::Vector3d::UnitZ());
  add(planeNormal(samples.ends, 0));  // the near ends
  add(planeNormal(samples.ends, 1));  // the far ends
  const std::size_t kept = std::min<std::size_t>(kRefinedSeeds, seeds.size());
  std::partial_sort(seeds.begin(), seeds.begin() + static_cast<std::ptrdiff_t>(kept), seeds.end(),
                    [](const Candidate& a, const Candidate& b) { return a.width < b.width; });
  Candidate best = refine(samples, seeds[0]);
  for (std::size_t i = 1; i < kept; ++i) {
    const Candidate c = refine(samples, seeds[i]);
    if (c.width < best.width)
      best = c;
  }
  return best.direction;
}

ContactNormal contactNormal(const OverlapSamples& samples,
                            std::span<const Eigen::Vector3d> verticesA,
                            std::span<const Eigen::Vector3d> verticesB) {
  ContactNormal c;
  Eigen::Vector3d n = thinnestDirection(samples);
  // Translation of B along +n that separates the blocks, and along -n.
  const double alongPlus = support(verticesA, n) + support(verticesB, -n);
  const double alongMinus = support(verticesB, n) + support(verticesA, -n);
  Eigen::Index largest = 0;
  n.cwiseAbs().maxCoeff(&largest);
  if (alongMinus < alongPlus || (alongMinus == alongPlus && n[largest] < 0.0))
    n = -n;
  c.normal = n;
  c.depth = overlapWidth(samples, n);
  return c;
}

}  // namespace recode::core
