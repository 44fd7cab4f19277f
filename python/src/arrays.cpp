// The module's NumPy checks and views (arrays.hpp). Every error names the argument and says
// what was given and what is allowed, as the C++ API's messages do (docs/api.md#python).
#include "arrays.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace recode::python {

namespace {

std::string shapeText(const py::array& a) {
  std::ostringstream s;
  s << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i)
    s << (i ? ", " : "") << a.shape(i);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

std::string dtypeText(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

// Any array-like (a NumPy array, nested lists) as an array; a TypeError for anything else.
py::array asArray(const py::handle& object, const std::string& what) {
  py::array a = py::array::ensure(object);
  if (!a)
    throw py::type_error(what + ": expected an array (a NumPy array or nested lists), got " +
                         py::str(py::type::of(object)).cast<std::string>());
  return a;
}

void requireShape(const py::array& a, const std::string& what, py::ssize_t rows,
                  py::ssize_t columns, const std::string& expected) {
  const bool ok = a.ndim() == 2 && (rows < 0 || a.shape(0) == rows) && a.shape(1) == columns;
  if (!ok)
    throw py::value_error(what + ": expected " + expected + ", got shape " + shapeText(a));
}

// float64 values of a real array; a TypeError for strings, objects, complex numbers, booleans.
py::array_t<double, py::array::c_style | py::array::forcecast> realArray(const py::handle& object,
                                                                         const std::string& what) {
  py::array a = asArray(object, what);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(what + ": expected real numbers, got dtype " + dtypeText(a));
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

void requireFinite(const double* values, py::ssize_t count, py::ssize_t columns,
                   const std::string& what) {
  for (py::ssize_t i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) {
      std::ostringstream s;
      s << what << "[" << i / columns << ", " << i % columns << "] is " << values[i]
        << ": coordinates must be finite";
      throw py::value_error(s.str());
    }
  }
}

Eigen::Matrix3d rotationFrom(const py::handle& object) {
  const auto a = realArray(object, "rotation");
  requireShape(a, "rotation", 3, 3, "a 3 x 3 rotation matrix");
  requireFinite(a.data(), 9, 3, "rotation");
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r(i, j) = a.at(i, j);
  return r;
}

void requireRotation(const Eigen::Matrix3d& r, const std::string& what) {
  const double orthogonality =
      (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality > kRotationTolerance) {
    std::ostringstream s;
    s << what << " is not a rotation: R^T R differs from the identity by " << orthogonality
      << " (at most " << kRotationTolerance
      << " allowed; poses are rigid motions, without scaling or shearing)";
    throw py::value_error(s.str());
  }
  if (r.determinant() < 0.0)
    throw py::value_error(what + " is a reflection (determinant " +
                          std::to_string(r.determinant()) + "), not a rotation");
}

}  // namespace

std::vector<Eigen::Vector3d> verticesFrom(const py::handle& array, const std::string& what) {
  const auto a = realArray(array, what);
  requireShape(a, what, -1, 3, "an (n, 3) array of vertex coordinates");
  requireFinite(a.data(), a.size(), 3, what);
  std::vector<Eigen::Vector3d> vertices(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertices[i] = Eigen::Vector3d(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
  return vertices;
}

std::vector<core::Triangle> facesFrom(const py::handle& array, std::size_t vertexCount,
                                      const std::string& what) {
  py::array raw = asArray(array, what);
  const char kind = raw.dtype().kind();
  // A float array of indices would be truncated silently by a cast: refused instead.
  if (kind != 'i' && kind != 'u')
    throw py::type_error(what + ": expected integer vertex indices, got dtype " + dtypeText(raw));
  requireShape(raw, what, -1, 3, "an (m, 3) array of vertex indices");
  // Unsigned 64-bit indices above 2^63 would wrap in int64: compare them unsigned.
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(raw);
  const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(raw);
  std::vector<core::Triangle> faces(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t index = a.data()[3 * i + k];
      const bool tooLarge = kind == 'u' ? u.data()[3 * i + k] >= vertexCount
                                        : index >= static_cast<std::int64_t>(vertexCount);
      if (index < 0 && kind == 'i')
        throw py::value_error(what + "[" + std::to_string(i) + ", " + std::to_string(k) + "] is " +
                              std::to_string(index) +
                              ": vertex indices count from 0 (negative indices are not allowed)");
      if (tooLarge) {
        const std::string value =
            kind == 'u' ? std::to_string(u.data()[3 * i + k]) : std::to_string(index);
        throw py::value_error(what + "[" + std::to_string(i) + ", " + std::to_string(k) + "] is " +
                              value + ": there are " + std::to_string(vertexCount) +
                              " vertices, so indices run from 0 to " +
                              std::to_string(static_cast<long long>(vertexCount) - 1));
      }
      faces[i][k] = static_cast<core::VertexIndex>(index);
    }
  }
  return faces;
}

Eigen::Isometry3d poseFrom(const py::handle& matrix) {
  const auto a = realArray(matrix, "pose");
  requireShape(a, "pose", 4, 4, "a 4 x 4 matrix [[R, t], [0, 0, 0, 1]]");
  requireFinite(a.data(), 16, 4, "pose");
  if (a.at(3, 0) != 0.0 || a.at(3, 1) != 0.0 || a.at(3, 2) != 0.0 || a.at(3, 3) != 1.0) {
    std::ostringstream s;
    s << "pose: the last row is [" << a.at(3, 0) << ", " << a.at(3, 1) << ", " << a.at(3, 2) << ", "
      << a.at(3, 3) << "], it must be [0, 0, 0, 1] (a rigid motion)";
    throw py::value_error(s.str());
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      pose.matrix()(i, j) = a.at(i, j);
  requireRotation(pose.linear(), "pose: the upper-left 3 x 3 block");
  return pose;
}

Eigen::Isometry3d poseFrom(const std::optional<py::object>& rotation,
                           const std::optional<py::object>& translation) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (rotation && !rotation->is_none()) {
    const Eigen::Matrix3d r = rotationFrom(*rotation);
    requireRotation(r, "rotation");
    pose.linear() = r;
  }
  if (translation && !translation->is_none()) {
    const auto t = realArray(*translation, "translation");
    if (t.ndim() != 1 || t.shape(0) != 3)
      throw py::value_error("translation: expected 3 numbers, got shape " + shapeText(t));
    requireFinite(t.data(), 3, 3, "translation");
    pose.translation() = Eigen::Vector3d(t.data()[0], t.data()[1], t.data()[2]);
  }
  return pose;
}

Eigen::Isometry3d poseFromArguments(const std::optional<py::object>& matrix,
                                    const std::optional<py::object>& rotation,
                                    const std::optional<py::object>& translation) {
  const bool hasMatrix = matrix && !matrix->is_none();
  const bool hasParts =
      (rotation && !rotation->is_none()) || (translation && !translation->is_none());
  if (hasMatrix && hasParts)
    throw py::value_error(
        "give the pose as a 4 x 4 matrix or as rotation and translation, not both");
  return hasMatrix ? poseFrom(*matrix) : poseFrom(rotation, translation);
}

py::array_t<double> matrixOf(const Eigen::Isometry3d& pose) {
  py::array_t<double> m({4, 4});
  auto w = m.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      w(i, j) = pose.matrix()(i, j);
  return m;
}

py::array pointsView(const std::vector<Eigen::Vector3d>& points, const py::handle& owner) {
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d holds 3 doubles");
  py::array view(py::dtype::of<double>(), {static_cast<long>(points.size()), 3L},
                 {static_cast<long>(sizeof(Eigen::Vector3d)), static_cast<long>(sizeof(double))},
                 points.empty() ? nullptr : points.front().data(), owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

}  // namespace recode::python
