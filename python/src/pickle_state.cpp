#include "pickle_state.hpp"

namespace recode::python {

void checkState(const py::tuple& state, const char* type, std::size_t items) {
  const std::string expected = "a tuple of the format version " + std::to_string(kPickleFormat) +
                               " and " + std::to_string(items) + " items";
  if (state.empty())
    throw py::value_error(std::string(type) + ": the pickled state is an empty tuple, expected " +
                          expected);
  const py::object version = state[0];
  if (!py::isinstance<py::int_>(version) || version.cast<long long>() != kPickleFormat)
    throw py::value_error(std::string(type) + ": the pickled state is of format " +
                          py::repr(version).cast<std::string>() + ", this module reads format " +
                          std::to_string(kPickleFormat) +
                          " (pickled by another version of recode? pickle it again with this "
                          "one)");
  if (state.size() != items + 1)
    throw py::value_error(std::string(type) + ": the pickled state has " +
                          std::to_string(state.size() - 1) + " items after the version, expected " +
                          expected);
}

py::array_t<double> pointsState(const std::vector<Eigen::Vector3d>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  double* d = out.mutable_data();
  for (const Eigen::Vector3d& p : points)
    for (int k = 0; k < 3; ++k)
      *d++ = p[k];
  return out;
}

std::vector<Eigen::Vector3d> pointsFromState(const py::handle& array, const char* type,
                                             const char* what) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a || a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(type) + ": the pickled state's " + what +
                          " are not an (n, 3) array");
  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = Eigen::Vector3d(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
  return points;
}

}  // namespace recode::python
