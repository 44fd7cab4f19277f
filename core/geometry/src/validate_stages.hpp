#pragma once
// Internal to checkConvexBlock (not installed, not public API): what its stages share. The
// stages are split by job over validate.cpp (stages 1-3 and 5, and the order they run in),
// validate_topology.cpp (stage 4) and validate_convexity.cpp (stages 6 and 7); validate.hpp
// lists the stages and docs/geometry.md their messages.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/validate.hpp"

namespace recode::core::detail {

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

// "triangle 5 (vertices 1, 2, 3)", as the messages name a triangle.
inline std::string triangleName(std::size_t t, const Triangle& tri) {
  return "triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) + ", " +
         std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")";
}

// The mesh's vertices relative to its bounding-box centre, which gives better conditioned
// planes than the file's coordinates, with the lengths the geometric stages measure against.
struct CentredPoints {
  std::vector<Eigen::Vector3d> points;  // vertices[i] - centre, same order
  double diagonal = 0.0;                // of the bounding box
  double tolerance = 0.0;               // relativeTolerance * diagonal
};

// Stage 4 (validate_topology.cpp): closed, manifold, consistently oriented, one surface
// without handles. Needs stage 2 only. Returns true if it found a problem.
bool checkTopology(const TriangleMesh& mesh, std::size_t usedVertexCount, Recorder& recorder);

// Stage 6 (validate_convexity.cpp): no vertex more than the tolerance in front of any
// triangle's plane. Needs stages 1-5. Returns true if it found a problem.
bool checkConvexity(const TriangleMesh& mesh, const CentredPoints& centred, Recorder& recorder);

// Stage 7 (validate_convexity.cpp): the surface winds once around its interior. Needs
// stages 1-6.
void checkSingleWinding(const TriangleMesh& mesh, const CentredPoints& centred, Recorder& recorder);

}  // namespace recode::core::detail
