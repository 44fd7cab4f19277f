// The leaves' world boxes (core/sim/src/posed_vertex_box.hpp): the SIMD path gives the bits of
// the box of transformed()'s vertices, for any vertex count (full vectors and a tail), for
// rotations with and without a reflection, and where the scalar loop's order decides a bit:
// extremes at +0 and -0, and NaN coordinates.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <Eigen/Geometry>

#include "posed_vertex_box.hpp"
#include "recode/geometry/mesh.hpp"

using namespace recode::core;

namespace {

// Bit for bit, so that +0 and -0 (and NaN payloads) count as different.
bool sameBits(const Aabb& a, const Aabb& b) {
  return std::memcmp(a.min.data(), b.min.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.max.data(), b.max.data(), 3 * sizeof(double)) == 0;
}

// The definition: every vertex through transformed(), then their box.
Aabb boxOfTransformed(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  Aabb box;
  for (const Eigen::Vector3d& v : transformed(mesh, pose).vertices)
    box.extend(v);
  return box;
}

Aabb posed(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  return detail::posedVertexBox(mesh.vertices, pose.linear(), pose.translation());
}

Eigen::Isometry3d randomPose(std::mt19937_64& rng, double reach, bool reflect) {
  std::normal_distribution<double> normal;
  const Eigen::Quaterniond q =
      Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.toRotationMatrix();
  if (reflect)
    pose.linear().col(1) *= -1.0;
  pose.translation() = reach * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  return pose;
}

}  // namespace

TEST_CASE("posedVertexBox: the bits of transformed()'s box for random blocks and poses",
          "[hierarchy][posed-box]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  for (int trial = 0; trial < 2000; ++trial) {
    // 0 to 40 vertices: below one vector, whole vectors and every tail length.
    TriangleMesh mesh;
    const int count = trial % 41;
    for (int i = 0; i < count; ++i)
      mesh.vertices.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    const double reach = std::pow(10.0, std::uniform_int_distribution<int>(-3, 6)(rng));
    const Eigen::Isometry3d pose = randomPose(rng, reach, trial % 2 == 1);
    const Aabb expected = boxOfTransformed(mesh, pose);
    REQUIRE(sameBits(detail::posedVertexBoxScalar(mesh.vertices, pose.linear(), pose.translation()),
                     expected));
    INFO("trial " << trial << ", " << count << " vertices");
    REQUIRE(sameBits(posed(mesh, pose), expected));
  }
}

TEST_CASE("posedVertexBox: zero extremes keep the scalar loop's signs, NaN its NaNs",
          "[hierarchy][posed-box]") {
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  // Every axis reversed with a translation of -0: the zeros, of both signs again, become the
  // box's upper ends.
  Eigen::Isometry3d mirror = Eigen::Isometry3d::Identity();
  mirror.linear() = -Eigen::Matrix3d::Identity();
  mirror.translation() = Eigen::Vector3d::Constant(-0.0);
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    // Every coordinate in [0, 1] with some exactly +0 and some -0, so that both ends of the
    // box can be a zero reached by vertices of either sign, in the SIMD part and in the tail.
    TriangleMesh mesh;
    const int count = 3 + trial % 29;
    for (int i = 0; i < count; ++i) {
      Eigen::Vector3d v;
      for (int k = 0; k < 3; ++k) {
        const int pick = std::uniform_int_distribution<int>(0, 3)(rng);
        v[k] = pick == 0   ? 0.0
               : pick == 1 ? -0.0
                           : std::uniform_real_distribution<double>(0, 1)(rng);
      }
      mesh.vertices.push_back(v);
    }
    INFO("trial " << trial);
    REQUIRE(sameBits(posed(mesh, identity), boxOfTransformed(mesh, identity)));
    REQUIRE(sameBits(posed(mesh, mirror), boxOfTransformed(mesh, mirror)));
  }
  // Non-finite vertices (a mesh built in code is not validated): a NaN coordinate, and an
  // infinity that a zero matrix entry turns into NaN, at every position of 19 vertices (in a
  // vector and in the tail), under the identity and a turn.
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() << 0.6, -0.8, 0.0, 0.8, 0.6, 0.0, 0.0, 0.0, 1.0;
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    for (int at = 0; at < 19; ++at) {
      TriangleMesh mesh;
      for (int i = 0; i < 19; ++i)
        mesh.vertices.emplace_back(1.0 + i, 2.0 - i, 0.5 * i);
      mesh.vertices[static_cast<std::size_t>(at)].x() = bad;
      INFO("bad coordinate " << bad << " at vertex " << at);
      REQUIRE(sameBits(posed(mesh, identity), boxOfTransformed(mesh, identity)));
      REQUIRE(sameBits(posed(mesh, turn), boxOfTransformed(mesh, turn)));
    }
  }
}

TEST_CASE("posedVertexBox: a box whose every end is a zero has the scalar loop's signs",
          "[hierarchy][posed-box]") {
  // Every coordinate +0 or -0, and a translation of -0 (which keeps a sum's sign): every end of
  // the box is a zero of a sign that the order of the comparisons decides, and no end is
  // anything else, so nothing but the zeros can send the box back to the scalar loop.
  Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  identity.translation() = Eigen::Vector3d::Constant(-0.0);
  Eigen::Isometry3d mirror = identity;
  mirror.linear() = -Eigen::Matrix3d::Identity();
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 200; ++trial) {
    TriangleMesh mesh;
    const int count = 4 + trial % 37;
    for (int i = 0; i < count; ++i) {
      Eigen::Vector3d v;
      for (int k = 0; k < 3; ++k)
        v[k] = std::uniform_int_distribution<int>(0, 1)(rng) == 0 ? 0.0 : -0.0;
      mesh.vertices.push_back(v);
    }
    INFO("trial " << trial);
    REQUIRE(sameBits(posed(mesh, identity), boxOfTransformed(mesh, identity)));
    REQUIRE(sameBits(posed(mesh, mirror), boxOfTransformed(mesh, mirror)));
  }
}
