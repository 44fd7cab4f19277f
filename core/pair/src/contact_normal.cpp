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

// The corners of the 2-D convex hull of points (x, y), by Andrew's monotone chain; points on
// an edge between corners are dropped. Appends their indices in `points` to `corners`;
// `order` is scratch space.
void appendHull2d(const std::vector<std::array<double, 2>>& points,
                  std::vector<std::size_t>& corners, std::vector<std::size_t>& order) {
  order.resize(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return points[i] < points[j]; });
  const auto cross = [&](std::size_t o, std::size_t a, std::size_t b) {
    return (points[a][0] - points[o][0]) * (points[b][1] - points[o][1]) -
           (points[a][1] - points[o][1]) * (points[b][0] - points[o][0]);
  };
  const std::size_t start = corners.size();
  for (int pass = 0; pass < 2; ++pass) {  // lower chain, then upper chain
    const std::size_t chainStart = corners.size();
    for (std::size_t k = 0; k < order.size(); ++k) {
      const std::size_t i = pass == 0 ? order[k] : order[order.size() - 1 - k];
      while (corners.size() >= chainStart + 2 &&
             cross(corners[corners.size() - 2], corners.back(), i) <= 0.0)
        corners.pop_back();
      corners.push_back(i);
    }
    corners.pop_back();  // the chain's last point starts the other chain
  }
  if (corners.size() == start && !order.empty())
    corners.push_back(order.front());  // all points equal
}

// The ends that can be extreme along some direction, found row by row. Ends that share one
// coordinate exactly (a pixel row: the same world coordinate along the image's other axis)
// are extreme only at corners of their 2-D hull in the other two coordinates, because a
// linear function's least and greatest values over points are reached at corners of their
// hull. So the width along every direction is the same over these ends as over all of them
// (up to the rounding of the hull's orientation tests), and a contact of N pixels in R rows
// keeps a few ends per row instead of 2N. Rows are the longest runs of consecutive ends equal
// along `axis`; the pair algorithm gives the ends pixel after pixel, row after row.
std::vector<Eigen::Vector3d> rowExtremes(std::span<const Eigen::Vector3d> ends, int axis) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  std::vector<Eigen::Vector3d> kept;
  std::vector<std::array<double, 2>> row;
  std::vector<std::size_t> corners, order;
  std::size_t first = 0;
  while (first < ends.size()) {
    std::size_t end = first + 1;
    while (end < ends.size() && ends[end][axis] == ends[first][axis])
      ++end;
    row.clear();
    corners.clear();
    for (std::size_t i = first; i < end; ++i)
      row.push_back({ends[i][a], ends[i][b]});
    appendHull2d(row, corners, order);
    for (const std::size_t c : corners)
      kept.push_back(ends[first + c]);
    first = end;
  }
  return kept;
}

// Consecutive runs of ends equal along `axis`.
std::size_t runCount(std::span<const Eigen::Vector3d> ends, int axis) {
  std::size_t runs = ends.empty() ? 0 : 1;
  for (std::size_t i = 1; i < ends.size(); ++i)
    runs += ends[i][axis] != ends[i - 1][axis] ? 1 : 0;
  return runs;
}

// rowExtremes along the image axis whose rows are longest (halfPixel is non-zero along the
// two image axes); empty when rows are too short to save anything (then every end is used).
std::vector<Eigen::Vector3d> extremeEnds(const OverlapSamples& samples) {
  int rowAxis = -1;
  std::size_t fewest = samples.ends.size() / 4;
  for (int axis = 0; axis < 3; ++axis) {
    if (samples.halfPixel[axis] == 0.0)
      continue;
    const std::size_t runs = runCount(samples.ends, axis);
    if (runs < fewest) {
      fewest = runs;
      rowAxis = axis;
    }
  }
  if (rowAxis < 0)
    return {};
  return rowExtremes(samples.ends, rowAxis);
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

Eigen::Vector3d thinnestDirection(const OverlapSamples& all) {
  // Widths from the extreme ends alone (the same widths); the plane fits use every end.
  const std::vector<Eigen::Vector3d> extremes = extremeEnds(all);
  const OverlapSamples samples = extremes.empty() ? all : OverlapSamples{extremes, all.halfPixel};
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
  add(planeNormal(all.ends, 0));  // the near ends
  add(planeNormal(all.ends, 1));  // the far ends
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
