#pragma once
// What a block occupies along lines parallel to the view axis: the CGAL judgement's double-
// precision geometry, in the plane coordinates (u, v, d) of core::OrthoView::toPlane, where d
// is the coordinate along the view axis (larger d is nearer the viewer). Internal to verify.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/view.hpp"

namespace recode::verify {

// A closed range of d.
struct AxisRange {
  double lo = 0.0;
  double hi = 0.0;
};

class ViewLineProbe {
 public:
  // The block's triangles whose projections meet the image-plane rectangle [u0, u1] x [v0, v1]:
  // later queries must stay inside it. Throws std::invalid_argument for a vertex index out of
  // range.
  ViewLineProbe(const core::TriangleMesh& mesh, const core::OrthoView& view, double u0, double v0,
                double u1, double v1);

  // Where the line through (u, v) along the axis meets the block; nullopt if it misses it. A
  // line through an edge counts as meeting both triangles beside it (barycentric coordinates
  // down to -1e-12 are accepted), so the rounding of doubles cannot open a crack.
  [[nodiscard]] std::optional<AxisRange> line(double u, double v) const;

  // The range of d the block occupies within the prism [u0, u1] x [v0, v1] x R: that of its
  // surface there, found by clipping every triangle to the prism. nullopt if the block does
  // not reach into the prism.
  [[nodiscard]] std::optional<AxisRange> prism(double u0, double v0, double u1, double v1) const;

 private:
  struct PlaneTriangle {
    std::array<Eigen::Vector3d, 3> p;  // (u, v, d) of the corners
    double umin, vmin, umax, vmax;     // box of the projection
  };
  std::vector<PlaneTriangle> triangles_;
};

}  // namespace recode::verify
