// Stages 6 and 7 of checkConvexBlock: convexity (no vertex in front of any triangle's plane)
// and single winding (the surface covers its interior once). They run only on a closed,
// outward-oriented surface, which stages 1-5 have established.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "format.hpp"
#include "validate_stages.hpp"

namespace recode::core::detail {
namespace {

// ---------------------------------------------------------------------------------------
// Bounding-volume hierarchy over points, for the convexity search: a binary tree of
// oriented boxes (axes from the principal components of each node's points), with the
// points stored contiguously (structure of arrays) in the order of the tree's leaves.
//
// Oriented boxes matter here: the points of a convex mesh lie on its surface, and a node's
// points form a surface patch. An oriented box around a patch of size L is thin across the
// surface, so against a face plane it only reaches across the plane when the patch is
// within a few L of the face; an axis-aligned box reaches about L across any oblique plane,
// so many more nodes near each face would have to be opened.

class PointTree {
 public:
  explicit PointTree(const std::vector<Eigen::Vector3d>& points) {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0U);
    nodes_.reserve(2 * (n / kLeafSize + 1));
    build(points, order);
    x_.resize(n);
    y_.resize(n);
    z_.resize(n);
    index_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d& p = points[order[i]];
      x_[i] = p.x();
      y_[i] = p.y();
      z_[i] = p.z();
      index_[i] = order[i];
    }
  }

  struct Farthest {
    double distance = 0.0;    // n . p - offset of the farthest point found
    std::uint32_t index = 0;  // its original index
    bool found = false;
  };

  // The point with the largest signed distance n . p - offset among those with distance
  // > threshold (ties: the lowest index). Subtrees whose box lies wholly at or below
  // threshold - slack are skipped; slack absorbs rounding in the box bound.
  [[nodiscard]] Farthest farthestAbove(const Eigen::Vector3d& normal, double offset,
                                       double threshold, double slack) const {
    Farthest best;
    std::uint32_t stack[128];
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      const double bound =
          normal.dot(node.center) + (node.axes * normal).cwiseAbs().dot(node.half) - offset;
      if (bound + slack <= threshold) {
        continue;
      }
      if (node.count > 0) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          const double d = normal.x() * x_[i] + normal.y() * y_[i] + normal.z() * z_[i] - offset;
          if (d > threshold && (!best.found || d > best.distance ||
                                (d == best.distance && index_[i] < best.index))) {
            best = {d, index_[i], true};
          }
        }
      } else {
        stack[top++] = node.first;      // left child
        stack[top++] = node.first + 1;  // right child
      }
    }
    return best;
  }

 private:
  static constexpr std::size_t kLeafSize = 8;

  struct Node {
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // rows: the box's unit axes
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    Eigen::Vector3d half = Eigen::Vector3d::Zero();  // half extents along the axes
    std::uint32_t first = 0;  // leaf: first point; inner: index of the left child (right = +1)
    std::uint32_t count = 0;  // leaf: number of points; inner: 0
  };

  // The box around points order[begin, end), oriented along the principal axes of those
  // points (the identity when the eigensolver fails, so the box is then axis-aligned).
  static Node fitNode(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t i = begin; i < end; ++i) {
      mean += points[order[i]];
    }
    mean /= static_cast<double>(end - begin);
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d d = points[order[i]] - mean;
      covariance.noalias() += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    Node node;
    if (solver.info() == Eigen::Success && solver.eigenvectors().allFinite()) {
      // Eigenvalues ascend, so the last row is the axis of largest variance.
      node.axes = solver.eigenvectors().transpose();
    }
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d q = node.axes * points[order[i]];
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    node.center = node.axes.transpose() * (0.5 * (lo + hi));
    node.half = 0.5 * (hi - lo);
    return node;
  }

  // Reorders order[begin, end) so that its first half holds the points with the smaller
  // projections on the node's axis of largest extent: the split of an inner node. keyed
  // is scratch space, kept by the caller to avoid an allocation per node.
  static void splitAtMedian(const std::vector<Eigen::Vector3d>& points, const Node& node,
                            std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end,
                            std::vector<std::pair<double, std::uint32_t>>& keyed) {
    int axis = 0;
    node.half.maxCoeff(&axis);
    const Eigen::Vector3d direction = node.axes.row(axis).transpose();
    keyed.clear();
    for (std::size_t i = begin; i < end; ++i) {
      keyed.emplace_back(direction.dot(points[order[i]]), order[i]);
    }
    const std::size_t size = end - begin;
    const std::size_t half = size / 2;
    std::nth_element(keyed.begin(), keyed.begin() + static_cast<std::ptrdiff_t>(half), keyed.end());
    for (std::size_t i = 0; i < size; ++i) {
      order[begin + i] = keyed[i].second;
    }
  }

  // Builds the tree over order[0, n): each node's box is oriented along the principal axes
  // of its points; inner nodes split at the median along the axis of largest extent.
  // Children are allocated as a pair so that a node stores one child index.
  void build(const std::vector<Eigen::Vector3d>& points, std::vector<std::uint32_t>& order) {
    struct Item {
      std::size_t node, begin, end;
    };
    nodes_.push_back({});
    std::vector<Item> work{{0, 0, order.size()}};
    std::vector<std::pair<double, std::uint32_t>> keyed;
    while (!work.empty()) {
      const Item item = work.back();
      work.pop_back();
      const std::size_t size = item.end - item.begin;
      Node node = fitNode(points, order, item.begin, item.end);
      if (size <= kLeafSize) {
        node.first = static_cast<std::uint32_t>(item.begin);
        node.count = static_cast<std::uint32_t>(size);
        nodes_[item.node] = node;
        continue;
      }
      splitAtMedian(points, node, order, item.begin, item.end, keyed);
      const std::size_t half = size / 2;
      const std::size_t left = nodes_.size();
      nodes_.push_back({});
      nodes_.push_back({});
      node.first = static_cast<std::uint32_t>(left);
      nodes_[item.node] = node;
      work.push_back({left, item.begin, item.begin + half});
      work.push_back({left + 1, item.begin + half, item.end});
    }
  }

  std::vector<Node> nodes_;
  std::vector<double> x_, y_, z_;
  std::vector<std::uint32_t> index_;
};

}  // namespace

// A convex surface lies wholly behind the plane of each of its faces, so a vertex in front
// of one (by more than the tolerance, which absorbs rounding in flat, finely tessellated
// faces) is a dent. Each triangle reports its farthest offending vertex.
bool checkConvexity(const TriangleMesh& mesh, const CentredPoints& centred, Recorder& recorder) {
  const std::vector<Eigen::Vector3d>& points = centred.points;
  const double tolerance = centred.tolerance;
  const PointTree tree(points);
  const double slack = 1e-12 * centred.diagonal;
  bool found = false;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = points[tri[0]];
    const Eigen::Vector3d& b = points[tri[1]];
    const Eigen::Vector3d& c = points[tri[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    const double offset = normal.dot((a + b + c) / 3.0);
    const PointTree::Farthest far = tree.farthestAbove(normal, offset, tolerance, slack);
    if (far.found) {
      found = true;
      if (recorder.add(MeshProblemKind::NotConvex,
                       "vertex " + std::to_string(far.index) + " " +
                           formatPoint(mesh.vertices[far.index]) + " lies " +
                           formatDouble(far.distance) + " outside the plane of " +
                           triangleName(t, tri) + " (tolerance " + formatDouble(tolerance) +
                           "): the mesh is not convex")) {
        return true;
      }
    }
  }
  return found;
}

// A surface that passes stages 1-6 can still cover the solid twice (an octahedron whose
// equator is traversed twice), and a rasterizer would then count two front and two back
// faces per pixel. The total solid angle it subtends at the vertex centroid (inside, since
// the mesh is convex with positive volume), by the formula of Van Oosterom and Strackee, is
// 4*pi times the number of windings.
void checkSingleWinding(const TriangleMesh& mesh, const CentredPoints& centred,
                        Recorder& recorder) {
  const std::vector<Eigen::Vector3d>& points = centred.points;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) {
    centroid += p;
  }
  centroid /= static_cast<double>(points.size());
  double total = 0.0;
  for (const Triangle& tri : mesh.triangles) {
    const Eigen::Vector3d a = points[tri[0]] - centroid;
    const Eigen::Vector3d b = points[tri[1]] - centroid;
    const Eigen::Vector3d c = points[tri[2]] - centroid;
    const double la = a.norm();
    const double lb = b.norm();
    const double lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  const double windings = total / (4.0 * std::numbers::pi);
  if (std::abs(windings - 1.0) > 0.5) {
    recorder.add(MeshProblemKind::MultipleWinding,
                 "the surface winds " + formatDouble(std::round(windings)) +
                     " times around its interior (total solid angle " + formatDouble(total) +
                     "); a convex block's surface winds once");
  }
}

}  // namespace recode::core::detail
