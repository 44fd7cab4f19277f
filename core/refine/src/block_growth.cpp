#include "recode/refine/block_growth.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "recode/geometry/convex_hull.hpp"

namespace recode::core {

namespace {

// x + d rounded away from x (towards +inf for d > 0, -inf for d < 0): at least as far out as the
// exact sum. The error-free two-sum gives the rounding error of x + d exactly.
double sumRoundedOutward(double x, double d) {
  const double s = x + d;
  const double bv = s - x;
  const double av = s - bv;
  const double err = (x - av) + (d - bv);  // exact: x + d == s + err
  if (d > 0.0 && err > 0.0)
    return std::nextafter(s, std::numeric_limits<double>::infinity());
  if (d < 0.0 && err < 0.0)
    return std::nextafter(s, -std::numeric_limits<double>::infinity());
  return s;
}

}  // namespace

// Why a hull and not three sweeps: a sweep moves each face up or down by the sign of its
// normal's component along the axis, and the quads a sweep adds along edges nearly parallel to
// the axis have no reliable sign for the next one; a block turned by 1e-5 degrees lost a whole
// pixel that way. The hull takes no sign from rounded normals: its predicates are exact, and
// every corner sum is rounded outward, so for any direction n the hull's support is at least
// max over the vertices of n.v plus the box's support in n (the corner whose signs are n's is
// rounded outward along n).
TriangleMesh grownByBox(const TriangleMesh& block, const Eigen::Vector3d& half) {
  const int steps[3] = {half.x() > 0.0 ? 2 : 1, half.y() > 0.0 ? 2 : 1, half.z() > 0.0 ? 2 : 1};
  std::vector<Eigen::Vector3d> points;
  points.reserve(block.vertices.size() * static_cast<std::size_t>(steps[0] * steps[1] * steps[2]));
  for (const Eigen::Vector3d& v : block.vertices)
    for (int i = 0; i < steps[0]; ++i)
      for (int j = 0; j < steps[1]; ++j)
        for (int k = 0; k < steps[2]; ++k) {
          const int sign[3] = {i, j, k};
          Eigen::Vector3d p = v;
          for (int axis = 0; axis < 3; ++axis)
            if (steps[axis] == 2)
              p[axis] = sumRoundedOutward(v[axis], sign[axis] ? half[axis] : -half[axis]);
          points.push_back(p);
        }
  return convexHull(points, "a block grown by a box").mesh;
}

}  // namespace recode::core
