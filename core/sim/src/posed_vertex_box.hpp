#pragma once
// The world AABB of a leaf's vertices at a pose, as ObjectTree::updateAabbs needs it every
// frame for every leaf near another object: bit for bit the box of transformed()'s vertices
// (the pair algorithm's frame and MOR come from it, and skip-apart's proofs read it).

#include <span>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"

namespace recode::core::detail {

// Each vertex v goes to posedPoint(linear, translation, v), as in transformed(), and the box
// is the vertices' Aabb::extend. On a CPU with SIMD the vertices are transformed several at a time;
// a box with a zero coordinate (whose sign the order of the scalar comparisons decides) or any NaN
// is made again by the scalar loop, so the result never depends on the CPU.
[[nodiscard]] Aabb posedVertexBox(std::span<const Eigen::Vector3d> local,
                                  const Eigen::Matrix3d& linear,
                                  const Eigen::Vector3d& translation);

// The scalar loop alone: the definition the SIMD path must match (tests compare the two).
[[nodiscard]] Aabb posedVertexBoxScalar(std::span<const Eigen::Vector3d> local,
                                        const Eigen::Matrix3d& linear,
                                        const Eigen::Vector3d& translation);

}  // namespace recode::core::detail
