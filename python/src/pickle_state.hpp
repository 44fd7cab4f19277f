#pragma once
// Pickling the module's values (docs/api.md#pickling), and so copy.deepcopy, multiprocessing
// and dask: each class's __getstate__ is a tuple whose first item is the format version
// kPickleFormat and whose other items are arrays, numbers, strings and the module's own
// picklable objects; __setstate__ makes the value again through the same checks as the
// constructors (a block is validated again), so a state another version wrote, or a tampered
// one, is a clear ValueError and never a broken object.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace recode::python {

namespace py = pybind11;

// The layout of every state below; a change of any state's items changes it.
inline constexpr int kPickleFormat = 2;

// (kPickleFormat, items...).
template <class... Items>
[[nodiscard]] py::tuple makeState(Items&&... items) {
  return py::make_tuple(kPickleFormat, std::forward<Items>(items)...);
}

// A ValueError naming `type` ("recode.ConvexBlock") unless `state` is a tuple of `items` items
// after the version and its version is kPickleFormat.
void checkState(const py::tuple& state, const char* type, std::size_t items);

// Item `item` of a state as a T; a ValueError naming `type` and `what` when it is not one.
template <class T>
[[nodiscard]] T stateItem(const py::handle& item, const char* type, const char* what) {
  try {
    return item.cast<T>();
  } catch (const py::cast_error&) {
    throw py::value_error(std::string(type) + ": the pickled state's " + what +
                          " is not of the type written, got " +
                          py::str(py::type::of(item)).cast<std::string>());
  }
}

// The values of a 1-D array of exactly `count` numbers (converted to T); a ValueError naming
// `type` and `what` otherwise.
template <class T>
[[nodiscard]] std::vector<T> stateValues(const py::handle& array, std::size_t count,
                                         const char* type, const char* what) {
  const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.size()) != count)
    throw py::value_error(std::string(type) + ": the pickled state's " + what +
                          " is not an array of " + std::to_string(count) + " numbers");
  return {a.data(), a.data() + count};
}

// An (n, 3) float64 copy of the points, and the points of such an array (a ValueError naming
// `type` and `what` for any other shape).
[[nodiscard]] py::array_t<double> pointsState(const std::vector<Eigen::Vector3d>& points);
[[nodiscard]] std::vector<Eigen::Vector3d> pointsFromState(const py::handle& array,
                                                           const char* type, const char* what);

// A 1-D array of the values.
template <class T>
[[nodiscard]] py::array_t<T> stateArray(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace recode::python
