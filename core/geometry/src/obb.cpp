// Oriented bounding boxes: fitting (coordinate axes vs principal axes), rigid motion and the
// 15-axis separating-axis test.
#include "recode/geometry/obb.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace recode::core {

std::array<Eigen::Vector3d, 8> Obb::corners() const {
  std::array<Eigen::Vector3d, 8> out;
  for (int k = 0; k < 8; ++k) {
    Eigen::Vector3d p = center;
    for (int i = 0; i < 3; ++i)
      p += ((k >> i) & 1 ? 1.0 : -1.0) * halfExtents[i] * axes.col(i);
    out[static_cast<std::size_t>(k)] = p;
  }
  return out;
}

Obb Obb::transformed(const Eigen::Isometry3d& transform) const {
  Obb out;
  out.center = transform * center;
  out.axes = transform.linear() * axes;
  out.halfExtents = halfExtents;
  return out;
}

Aabb Obb::aabb() const {
  // The box's extent along world axis k is sum_i |axes(k, i)| * halfExtents[i].
  const Eigen::Vector3d reach = axes.cwiseAbs() * halfExtents;
  Aabb box;
  box.min = center - reach;
  box.max = center + reach;
  return box;
}

Obb fitObbWithAxes(std::span<const Eigen::Vector3d> points, const Eigen::Matrix3d& axes) {
  if (points.empty())
    throw std::invalid_argument("fitObbWithAxes: no points");
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d q = axes.transpose() * p;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  Obb box;
  box.axes = axes;
  box.center = axes * (0.5 * (lo + hi));
  box.halfExtents = 0.5 * (hi - lo);
  return box;
}

Obb fitObb(std::span<const Eigen::Vector3d> points) {
  if (points.empty())
    throw std::invalid_argument("fitObb: no points");
  Obb best = fitObbWithAxes(points, Eigen::Matrix3d::Identity());
  if (points.size() < 2)
    return best;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points)
    mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success)
    return best;
  Eigen::Matrix3d principal = solver.eigenvectors();
  if (principal.determinant() < 0.0)
    principal.col(2) = -principal.col(2);  // keep the axes right-handed
  const Obb candidate = fitObbWithAxes(points, principal);
  if (candidate.volume() < best.volume())
    best = candidate;
  return best;
}

Obb grown(const Obb& box, double margin) {
  Obb out = box;
  out.halfExtents.array() += margin;
  return out;
}

bool obbsOverlap(const Obb& a, const Obb& b) {
  // Everything in a's frame: R(i, j) = a_i . b_j, t = the centre offset in a's axes.
  const Eigen::Matrix3d r = a.axes.transpose() * b.axes;
  const Eigen::Vector3d t = a.axes.transpose() * (b.center - a.center);
  const Eigen::Matrix3d absR = r.cwiseAbs().array() + kObbParallelSlack;
  const Eigen::Vector3d& ea = a.halfExtents;
  const Eigen::Vector3d& eb = b.halfExtents;
  // A's face normals.
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > ea[i] + absR.row(i).dot(eb))
      return false;
  // B's face normals.
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(r.col(j))) > absR.col(j).dot(ea) + eb[j])
      return false;
  // a_i x b_j: in a's frame the axis has components only along the other two of a's axes,
  // and its dot products with b's axes are entries of R.
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = ea[i1] * absR(i2, j) + ea[i2] * absR(i1, j);
      const double rb = eb[j1] * absR(i, j2) + eb[j2] * absR(i, j1);
      if (std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j)) > ra + rb)
        return false;
    }
  }
  return true;
}

bool aabbsOverlap(const Aabb& a, const Aabb& b) {
  if (a.isEmpty() || b.isEmpty())
    return false;
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

}  // namespace recode::core
