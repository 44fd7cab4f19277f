#include "recode/geometry/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "format.hpp"

namespace recode::core {
namespace {

using detail::formatDouble;
using detail::formatPoint;

// Collects problems up to a limit.
class Recorder {
 public:
  Recorder(ValidationReport& report, std::size_t limit) : report_(report), limit_(limit) {}

  // Records a problem; returns true if the limit is now reached (the caller stops).
  bool add(MeshProblemKind kind, std::string message) {
    report_.problems.push_back({kind, std::move(message)});
    if (report_.problems.size() >= limit_) {
      report_.truncated = true;
      return true;
    }
    return false;
  }
  [[nodiscard]] bool full() const { return report_.problems.size() >= limit_; }
  [[nodiscard]] std::size_t count() const { return report_.problems.size(); }

 private:
  ValidationReport& report_;
  std::size_t limit_;
};

std::string triangleName(std::size_t t, const Triangle& tri) {
  return "triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) + ", " +
         std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")";
}

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

  // Builds the tree over order[0, n): each node's box is oriented along the principal axes
  // of its points; inner nodes split at the median along the axis of largest variance.
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

      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (std::size_t i = item.begin; i < item.end; ++i) {
        mean += points[order[i]];
      }
      mean /= static_cast<double>(size);
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for (std::size_t i = item.begin; i < item.end; ++i) {
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
      for (std::size_t i = item.begin; i < item.end; ++i) {
        const Eigen::Vector3d q = node.axes * points[order[i]];
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
      }
      node.center = node.axes.transpose() * (0.5 * (lo + hi));
      node.half = 0.5 * (hi - lo);

      if (size <= kLeafSize) {
        node.first = static_cast<std::uint32_t>(item.begin);
        node.count = static_cast<std::uint32_t>(size);
        nodes_[item.node] = node;
        continue;
      }
      // Split at the median of the projections on the axis of largest extent.
      int axis = 0;
      node.half.maxCoeff(&axis);
      const Eigen::Vector3d direction = node.axes.row(axis).transpose();
      keyed.clear();
      for (std::size_t i = item.begin; i < item.end; ++i) {
        keyed.emplace_back(direction.dot(points[order[i]]), order[i]);
      }
      const std::size_t half = size / 2;
      std::nth_element(keyed.begin(), keyed.begin() + static_cast<std::ptrdiff_t>(half),
                       keyed.end());
      for (std::size_t i = 0; i < size; ++i) {
        order[item.begin + i] = keyed[i].second;
      }
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

// ---------------------------------------------------------------------------------------
// Union-find for connected components.

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) {
      parent_[std::max(a, b)] = std::min(a, b);
    }
  }

 private:
  std::vector<std::size_t> parent_;
};

struct HalfEdge {
  std::uint64_t key;       // (min index << 32) | max index
  std::uint32_t triangle;  // the triangle using it
  bool forward;            // true if the triangle runs from the smaller to the larger index
};

std::string edgeName(std::uint64_t key) {
  return "edge (" + std::to_string(key >> 32) + ", " + std::to_string(key & 0xffffffffU) + ")";
}

// Stage 4. Returns true if it found a problem.
bool checkTopology(const TriangleMesh& mesh, std::size_t usedVertexCount, Recorder& recorder) {
  const std::size_t before = recorder.count();
  const std::vector<Triangle>& triangles = mesh.triangles;
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int k = 0; k < 3; ++k) {
      const VertexIndex a = tri[static_cast<std::size_t>(k)];
      const VertexIndex b = tri[static_cast<std::size_t>((k + 1) % 3)];
      if (a == b) {
        continue;  // repeated index: reported in stage 3
      }
      const std::uint64_t lo = std::min(a, b);
      const std::uint64_t hi = std::max(a, b);
      halfEdges.push_back({(lo << 32) | hi, static_cast<std::uint32_t>(t), a < b});
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& l, const HalfEdge& r) {
    return l.key < r.key || (l.key == r.key && l.triangle < r.triangle);
  });

  std::size_t edgeCount = 0;
  for (std::size_t i = 0; i < halfEdges.size();) {
    std::size_t j = i;
    std::size_t forward = 0;
    while (j < halfEdges.size() && halfEdges[j].key == halfEdges[i].key) {
      forward += halfEdges[j].forward ? 1 : 0;
      ++j;
    }
    const std::size_t uses = j - i;
    ++edgeCount;
    const std::uint64_t key = halfEdges[i].key;
    bool full = false;
    if (uses == 1) {
      full = recorder.add(MeshProblemKind::kOpenEdge,
                          edgeName(key) + " is used by only one triangle (triangle " +
                              std::to_string(halfEdges[i].triangle) + "): the mesh is not closed");
    } else if (uses > 2) {
      std::string list;
      for (std::size_t k = i; k < j && k < i + 4; ++k) {
        list += (k == i ? "" : ", ") + std::to_string(halfEdges[k].triangle);
      }
      if (uses > 4) {
        list += ", ...";
      }
      full =
          recorder.add(MeshProblemKind::kNonManifoldEdge,
                       edgeName(key) + " is used by " + std::to_string(uses) +
                           " triangles (triangles " + list + "); a closed surface uses it twice");
    } else if (forward != 1) {
      full = recorder.add(MeshProblemKind::kInconsistentOrientation,
                          edgeName(key) + " is used twice in the same direction (triangles " +
                              std::to_string(halfEdges[i].triangle) + " and " +
                              std::to_string(halfEdges[i + 1].triangle) +
                              "): inconsistent orientation");
    }
    if (full) {
      return true;
    }
    i = j;
  }
  if (recorder.count() > before) {
    return true;
  }

  DisjointSets sets(mesh.vertices.size());
  for (const Triangle& tri : triangles) {
    sets.unite(tri[0], tri[1]);
    sets.unite(tri[0], tri[2]);
  }
  // Count distinct roots among used vertices.
  std::vector<bool> isRoot(mesh.vertices.size(), false);
  std::size_t components = 0;
  for (const Triangle& tri : triangles) {
    for (const VertexIndex v : tri) {
      const std::size_t root = sets.find(v);
      if (!isRoot[root]) {
        isRoot[root] = true;
        ++components;
      }
    }
  }
  if (components > 1) {
    recorder.add(MeshProblemKind::kNotSingleSurface,
                 "the mesh has " + std::to_string(components) +
                     " connected components; a convex block is one closed surface");
    return true;
  }
  const long long euler = static_cast<long long>(usedVertexCount) -
                          static_cast<long long>(edgeCount) +
                          static_cast<long long>(triangles.size());
  if (euler != 2) {
    recorder.add(MeshProblemKind::kNotSingleSurface,
                 "Euler characteristic V - E + F = " + std::to_string(usedVertexCount) + " - " +
                     std::to_string(edgeCount) + " + " + std::to_string(triangles.size()) + " = " +
                     std::to_string(euler) + ", expected 2 (a closed surface without handles)");
    return true;
  }
  return false;
}

}  // namespace

std::string_view toString(MeshProblemKind kind) {
  switch (kind) {
    case MeshProblemKind::kNoTriangles:
      return "no triangles";
    case MeshProblemKind::kNonFiniteCoordinate:
      return "non-finite coordinate";
    case MeshProblemKind::kIndexOutOfRange:
      return "index out of range";
    case MeshProblemKind::kDegenerateTriangle:
      return "degenerate triangle";
    case MeshProblemKind::kUnusedVertex:
      return "unused vertex";
    case MeshProblemKind::kOpenEdge:
      return "open edge";
    case MeshProblemKind::kNonManifoldEdge:
      return "non-manifold edge";
    case MeshProblemKind::kInconsistentOrientation:
      return "inconsistent orientation";
    case MeshProblemKind::kNotSingleSurface:
      return "not a single surface";
    case MeshProblemKind::kInwardOrientation:
      return "inward orientation";
    case MeshProblemKind::kNotConvex:
      return "not convex";
    case MeshProblemKind::kMultipleWinding:
      return "multiple winding";
  }
  return "unknown problem";
}

ValidationReport checkConvexBlock(const TriangleMesh& mesh, double relativeTolerance,
                                  std::size_t maxProblems) {
  if (!std::isfinite(relativeTolerance) || relativeTolerance < 0.0) {
    throw std::invalid_argument(
        "checkConvexBlock: relativeTolerance must be finite and >= 0, got " +
        formatDouble(relativeTolerance));
  }
  if (maxProblems == 0) {
    throw std::invalid_argument("checkConvexBlock: maxProblems must be at least 1, got 0");
  }
  ValidationReport report;
  Recorder recorder(report, maxProblems);
  const std::vector<Eigen::Vector3d>& vertices = mesh.vertices;
  const std::vector<Triangle>& triangles = mesh.triangles;
  const std::size_t vertexCount = vertices.size();

  // Stage 1.
  if (triangles.empty()) {
    recorder.add(MeshProblemKind::kNoTriangles, "the mesh has no triangles");
    return report;
  }

  // Stage 2.
  for (std::size_t i = 0; i < vertexCount; ++i) {
    if (!vertices[i].allFinite()) {
      if (recorder.add(MeshProblemKind::kNonFiniteCoordinate, "vertex " + std::to_string(i) +
                                                                  " has a non-finite coordinate " +
                                                                  formatPoint(vertices[i]))) {
        return report;
      }
    }
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (const VertexIndex v : triangles[t]) {
      if (v >= vertexCount) {
        if (recorder.add(MeshProblemKind::kIndexOutOfRange,
                         "triangle " + std::to_string(t) + " has vertex index " +
                             std::to_string(v) + " out of range (" + std::to_string(vertexCount) +
                             " vertices)")) {
          return report;
        }
        break;
      }
    }
  }
  if (!report.ok()) {
    return report;
  }

  // Work in coordinates relative to the bounding-box centre: better conditioned planes.
  const Aabb box = boundingBox(mesh);
  const Eigen::Vector3d centre = box.center();
  const double diagonal = box.diagonal();
  const double tolerance = relativeTolerance * diagonal;
  std::vector<Eigen::Vector3d> points(vertexCount);
  for (std::size_t i = 0; i < vertexCount; ++i) {
    points[i] = vertices[i] - centre;
  }

  // Stage 3.
  std::vector<bool> used(vertexCount, false);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (const VertexIndex v : tri) {
      used[v] = true;
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      const VertexIndex repeated = tri[0] == tri[1] || tri[0] == tri[2] ? tri[0] : tri[1];
      if (recorder.add(
              MeshProblemKind::kDegenerateTriangle,
              triangleName(t, tri) + " repeats vertex index " + std::to_string(repeated))) {
        return report;
      }
      continue;
    }
    const Eigen::Vector3d& a = points[tri[0]];
    const Eigen::Vector3d& b = points[tri[1]];
    const Eigen::Vector3d& c = points[tri[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double height = longest > 0.0 ? (b - a).cross(c - a).norm() / longest : 0.0;
    if (!(height > tolerance)) {
      if (recorder.add(MeshProblemKind::kDegenerateTriangle,
                       triangleName(t, tri) + " has zero area: its height over its longest " +
                           "edge is " + formatDouble(height) + " (tolerance " +
                           formatDouble(tolerance) + ")")) {
        return report;
      }
    }
  }
  std::size_t usedVertexCount = 0;
  for (std::size_t i = 0; i < vertexCount; ++i) {
    if (used[i]) {
      ++usedVertexCount;
    } else if (recorder.add(MeshProblemKind::kUnusedVertex, "vertex " + std::to_string(i) + " " +
                                                                formatPoint(vertices[i]) +
                                                                " is not used by any triangle")) {
      return report;
    }
  }

  // Stage 4.
  if (checkTopology(mesh, usedVertexCount, recorder) || !report.ok()) {
    return report;
  }

  // Stage 5.
  const double volume = signedVolume(mesh);
  if (!(volume > 0.0)) {
    recorder.add(MeshProblemKind::kInwardOrientation,
                 "signed volume is " + formatDouble(volume) +
                     " (must be > 0): the faces point inward" +
                     (volume == 0.0 ? " or the mesh is flat" : ""));
    return report;
  }

  // Stage 6.
  {
    const PointTree tree(points);
    const double slack = 1e-12 * diagonal;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const Triangle& tri = triangles[t];
      const Eigen::Vector3d& a = points[tri[0]];
      const Eigen::Vector3d& b = points[tri[1]];
      const Eigen::Vector3d& c = points[tri[2]];
      const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
      const double offset = normal.dot((a + b + c) / 3.0);
      const PointTree::Farthest far = tree.farthestAbove(normal, offset, tolerance, slack);
      if (far.found) {
        if (recorder.add(MeshProblemKind::kNotConvex,
                         "vertex " + std::to_string(far.index) + " " +
                             formatPoint(vertices[far.index]) + " lies " +
                             formatDouble(far.distance) + " outside the plane of " +
                             triangleName(t, tri) + " (tolerance " + formatDouble(tolerance) +
                             "): the mesh is not convex")) {
          return report;
        }
      }
    }
    if (!report.ok()) {
      return report;
    }
  }

  // Stage 7: total solid angle subtended at the vertex centroid (inside, since the mesh is
  // convex with positive volume), by the formula of Van Oosterom and Strackee.
  {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) {
      centroid += p;
    }
    centroid /= static_cast<double>(vertexCount);
    double total = 0.0;
    for (const Triangle& tri : triangles) {
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
      recorder.add(MeshProblemKind::kMultipleWinding,
                   "the surface winds " + formatDouble(std::round(windings)) +
                       " times around its interior (total solid angle " + formatDouble(total) +
                       "); a convex block's surface winds once");
    }
  }
  return report;
}

void validateConvexBlock(const TriangleMesh& mesh, std::string_view sourceName,
                         double relativeTolerance) {
  const ValidationReport report = checkConvexBlock(mesh, relativeTolerance, 1);
  if (!report.ok()) {
    throw MeshError(std::string(sourceName) + ": " + report.problems.front().message);
  }
}

}  // namespace recode::core
