#pragma once
// NumPy in and out for the module: the checks that turn a wrong array into a ValueError or a
// TypeError naming the argument, its shape or dtype and the rule, before anything reaches the
// C++ API; and read-only NumPy views over the results' vectors, kept alive by their owner.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"

namespace recode::python {

namespace py = pybind11;

// An (n, 3) array of numbers (any real dtype, converted to float64), every one finite.
[[nodiscard]] std::vector<Eigen::Vector3d> verticesFrom(const py::handle& array,
                                                        const std::string& what);
// An (m, 3) array of integers (any integer dtype), each a vertex index below `vertexCount`.
[[nodiscard]] std::vector<core::Triangle> facesFrom(const py::handle& array,
                                                    std::size_t vertexCount,
                                                    const std::string& what);
// A rigid motion: a 4 x 4 matrix [[R, t], [0, 0, 0, 1]], or a 3 x 3 rotation and/or a
// 3-vector translation (the missing one the identity / zero). R must be a rotation within
// kRotationTolerance (no scaling, shearing or reflection): the API's poses are isometries.
inline constexpr double kRotationTolerance = 1e-6;
[[nodiscard]] Eigen::Isometry3d poseFrom(const py::handle& matrix);
[[nodiscard]] Eigen::Isometry3d poseFrom(const std::optional<py::object>& rotation,
                                         const std::optional<py::object>& translation);
// The pose given as either argument form; `matrix` and rotation/translation are exclusive.
[[nodiscard]] Eigen::Isometry3d poseFromArguments(const std::optional<py::object>& matrix,
                                                  const std::optional<py::object>& rotation,
                                                  const std::optional<py::object>& translation);

// A 4 x 4 float64 copy of the pose.
[[nodiscard]] py::array_t<double> matrixOf(const Eigen::Isometry3d& pose);
// Read-only (n, 3) float64 view of the points, its base `owner` (which must own them).
[[nodiscard]] py::array pointsView(const std::vector<Eigen::Vector3d>& points,
                                   const py::handle& owner);
// Read-only (rows, columns) view of a row-major buffer of `T`, its base `owner`.
template <class T>
[[nodiscard]] py::array gridView(const std::vector<T>& values, long rows, long columns,
                                 const py::handle& owner) {
  py::array view(py::dtype::of<T>(), {rows, columns},
                 {static_cast<long>(sizeof(T)) * columns, static_cast<long>(sizeof(T))},
                 values.data(), owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

}  // namespace recode::python
