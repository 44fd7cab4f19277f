#pragma once
// The pickled state of a CollisionResult (pickle_state.hpp): every field, down to each block
// contact's case map, frame and step times, so an unpickled result equals the original field by
// field.

#include <pybind11/pybind11.h>

#include "recode/api/collision.hpp"

namespace recode::python {

namespace py = pybind11;

[[nodiscard]] py::tuple resultState(const CollisionResult& result);
[[nodiscard]] CollisionResult resultFromState(const py::tuple& state);

}  // namespace recode::python
