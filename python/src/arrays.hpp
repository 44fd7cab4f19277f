#pragma once
// NumPy in and out for the module: the checks that turn a wrong array into a ValueError or a
// TypeError naming the argument, its shape or dtype and the rule, before anything reaches the
// C++ API; and read-only NumPy views over the results' vectors, kept alive by their owner.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"

namespace recode::python {

namespace py = pybind11;

// "(2, 3)", "(5,)": a shape as NumPy writes it, for messages.
[[nodiscard]] std::string shapeText(const std::vector<py::ssize_t>& shape);
[[nodiscard]] std::string shapeText(const py::array& a);
// "1, 2": the index of the `flat`-th entry (C order) of an array of `shape`, for messages.
[[nodiscard]] std::string indexText(const std::vector<py::ssize_t>& shape, std::size_t flat);
// The dtype as NumPy names it ("float64", "<U1").
[[nodiscard]] std::string dtypeText(const py::array& a);

// Any array-like (a NumPy array, nested lists) as an array; a TypeError for anything else.
[[nodiscard]] py::array asArray(const py::handle& object, const std::string& what);
// float64 values of a real array; a TypeError for strings, objects, complex numbers, booleans.
using RealArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
[[nodiscard]] RealArray realArray(const py::handle& object, const std::string& what);
// An array of integers (any integer dtype); a TypeError "WHAT: expected EXPECTED, got dtype D"
// for any other dtype (a float index would be truncated silently by a cast).
[[nodiscard]] py::array integerArray(const py::handle& object, const std::string& what,
                                     const std::string& expected);
// A ValueError "WHAT: expected EXPECTED, got shape S" unless `a` is (rows, columns); rows < 0
// allows any number of rows.
void requireShape(const py::array& a, const std::string& what, py::ssize_t rows,
                  py::ssize_t columns, const std::string& expected);

// The values of an integer array, C order, read without wrapping (unsigned 64-bit values above
// 2^63 stay unsigned). The first value below 0 or not below `end` is handed to `outside` (its
// flat index, the value as text, whether it is negative), which throws the caller's error.
using OutsideRange = std::function<void(std::size_t flat, const std::string& value, bool negative)>;
[[nodiscard]] std::vector<std::uint64_t> integersBelow(const py::array& integers, std::uint64_t end,
                                                       const OutsideRange& outside);

// What an array of indices indexes, for the messages: "vertex indices" into 8 "vertices".
struct IndexTarget {
  std::string indices;  // "vertex indices", "indices into objects"
  std::string items;    // "vertices", "objects"
  std::size_t count = 0;
};
// A (rows, columns) array of integers, each an index below target.count, row-major. Errors:
// "WHAT: expected integer INDICES, got dtype D" (TypeError), "WHAT: expected SHAPE, got shape S",
// "WHAT[i, k] is -1: INDICES count from 0 (...)", "WHAT[i, k] is 8: there are 8 ITEMS, so ...".
[[nodiscard]] std::vector<std::size_t> indexRows(const py::handle& array, const std::string& what,
                                                 py::ssize_t columns, const std::string& shape,
                                                 const IndexTarget& target);

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
// The name of what is checked, made only to word an error (a batch checks millions of poses).
using NameOf = std::function<std::string()>;
// A ValueError naming `what` unless r is a rotation within kRotationTolerance.
void requireRotation(const Eigen::Matrix3d& r, const NameOf& what);
// The rigid motion of a row-major 4 x 4 matrix of finite numbers; a ValueError "WHAT: the last
// row is [...], it must be [0, 0, 0, 1]" or "WHAT: the upper-left 3 x 3 block is not a
// rotation ..." for any other matrix.
[[nodiscard]] Eigen::Isometry3d rigidMotionFrom(const double* rowMajor, const NameOf& what);
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
