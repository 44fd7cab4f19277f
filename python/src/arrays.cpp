// The module's NumPy checks and views (arrays.hpp). Every error names the argument and says
// what was given and what is allowed, as the C++ API's messages do (docs/api.md#python).
#include "arrays.hpp"

#include <cmath>
#include <sstream>

namespace recode::python {

namespace {

std::string shapeOf(std::size_t dimensions, const std::function<py::ssize_t(std::size_t)>& size) {
  std::ostringstream s;
  s << '(';
  for (std::size_t i = 0; i < dimensions; ++i)
    s << (i ? ", " : "") << size(i);
  s << (dimensions == 1 ? ",)" : ")");
  return s.str();
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

}  // namespace

std::string shapeText(const std::vector<py::ssize_t>& shape) {
  return shapeOf(shape.size(), [&](std::size_t i) { return shape[i]; });
}

std::string shapeText(const py::array& a) {
  return shapeOf(static_cast<std::size_t>(a.ndim()),
                 [&](std::size_t i) { return a.shape(static_cast<py::ssize_t>(i)); });
}

std::string indexText(const std::vector<py::ssize_t>& shape, std::size_t flat) {
  std::vector<std::size_t> index(shape.size());
  for (std::size_t d = shape.size(); d-- > 0;) {
    index[d] = flat % static_cast<std::size_t>(shape[d]);
    flat /= static_cast<std::size_t>(shape[d]);
  }
  // A stream rather than string concatenation: GCC 12 at -O3 with LTO warns falsely
  // (-Wstringop-overflow) on `"..." + std::to_string(...)` here.
  std::ostringstream s;
  for (std::size_t d = 0; d < index.size(); ++d)
    s << (d ? ", " : "") << index[d];
  return s.str();
}

std::string dtypeText(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

py::array asArray(const py::handle& object, const std::string& what) {
  py::array a = py::array::ensure(object);
  if (!a)
    throw py::type_error(what + ": expected an array (a NumPy array or nested lists), got " +
                         py::str(py::type::of(object)).cast<std::string>());
  return a;
}

RealArray realArray(const py::handle& object, const std::string& what) {
  py::array a = asArray(object, what);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(what + ": expected real numbers, got dtype " + dtypeText(a));
  return RealArray::ensure(a);
}

py::array integerArray(const py::handle& object, const std::string& what,
                       const std::string& expected) {
  py::array a = asArray(object, what);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::type_error(what + ": expected " + expected + ", got dtype " + dtypeText(a));
  return a;
}

void requireShape(const py::array& a, const std::string& what, py::ssize_t rows,
                  py::ssize_t columns, const std::string& expected) {
  const bool ok = a.ndim() == 2 && (rows < 0 || a.shape(0) == rows) && a.shape(1) == columns;
  if (!ok)
    throw py::value_error(what + ": expected " + expected + ", got shape " + shapeText(a));
}

std::vector<std::uint64_t> integersBelow(const py::array& integers, std::uint64_t end,
                                         const OutsideRange& outside) {
  const bool isSigned = integers.dtype().kind() == 'i';
  const auto s =
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(integers);
  const auto u =
      py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(integers);
  std::vector<std::uint64_t> out(static_cast<std::size_t>(u.size()));
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (isSigned && s.data()[i] < 0)
      outside(i, std::to_string(s.data()[i]), true);
    if (u.data()[i] >= end)
      outside(i, std::to_string(u.data()[i]), false);
    out[i] = u.data()[i];
  }
  return out;
}

std::vector<std::size_t> indexRows(const py::handle& array, const std::string& what,
                                   py::ssize_t columns, const std::string& shape,
                                   const IndexTarget& target) {
  const py::array raw = integerArray(array, what, "integer " + target.indices);
  requireShape(raw, what, -1, columns, shape);
  const std::vector<py::ssize_t> dims{raw.shape(0), columns};
  const auto at = [&](std::size_t flat, const std::string& value) {
    return what + "[" + indexText(dims, flat) + "] is " + value + ": ";
  };
  const std::vector<std::uint64_t> values = integersBelow(
      raw, target.count, [&](std::size_t flat, const std::string& value, bool negative) {
        if (negative)
          throw py::value_error(at(flat, value) + target.indices +
                                " count from 0 (negative indices are not allowed)");
        throw py::value_error(at(flat, value) + "there are " + std::to_string(target.count) + " " +
                              target.items + ", so indices run from 0 to " +
                              std::to_string(static_cast<long long>(target.count) - 1));
      });
  return {values.begin(), values.end()};
}

void requireRotation(const Eigen::Matrix3d& r, const NameOf& what) {
  const double orthogonality =
      (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality > kRotationTolerance) {
    std::ostringstream s;
    s << what() << " is not a rotation: R^T R differs from the identity by " << orthogonality
      << " (at most " << kRotationTolerance
      << " allowed; poses are rigid motions, without scaling or shearing)";
    throw py::value_error(s.str());
  }
  if (r.determinant() < 0.0)
    throw py::value_error(what() + " is a reflection (determinant " +
                          std::to_string(r.determinant()) + "), not a rotation");
}

Eigen::Isometry3d rigidMotionFrom(const double* m, const NameOf& what) {
  if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0) {
    std::ostringstream s;
    s << what() << ": the last row is [" << m[12] << ", " << m[13] << ", " << m[14] << ", " << m[15]
      << "], it must be [0, 0, 0, 1] (a rigid motion)";
    throw py::value_error(s.str());
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      pose.matrix()(i, j) = m[4 * i + j];
  requireRotation(pose.linear(), [&] { return what() + ": the upper-left 3 x 3 block"; });
  return pose;
}

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
  const std::vector<std::size_t> indices =
      indexRows(array, what, 3, "an (m, 3) array of vertex indices",
                {"vertex indices", "vertices", vertexCount});
  std::vector<core::Triangle> faces(indices.size() / 3);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      faces[i][k] = static_cast<core::VertexIndex>(indices[3 * i + k]);
  return faces;
}

Eigen::Isometry3d poseFrom(const py::handle& matrix) {
  const auto a = realArray(matrix, "pose");
  requireShape(a, "pose", 4, 4, "a 4 x 4 matrix [[R, t], [0, 0, 0, 1]]");
  requireFinite(a.data(), 16, 4, "pose");
  return rigidMotionFrom(a.data(), [] { return std::string("pose"); });
}

Eigen::Isometry3d poseFrom(const std::optional<py::object>& rotation,
                           const std::optional<py::object>& translation) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (rotation && !rotation->is_none()) {
    const Eigen::Matrix3d r = rotationFrom(*rotation);
    requireRotation(r, [] { return std::string("rotation"); });
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
