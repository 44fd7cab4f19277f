#pragma once
// The parts of the module `recode`, each binding one header of the collision API
// (recode/api/*.hpp); module.cpp calls them in order, since later parts name earlier types.

#include <pybind11/pybind11.h>

namespace recode::python {

namespace py = pybind11;

void bindGeometry(py::module_& m);   // ConvexBlock, CollisionGeometry, the primitive solids
void bindCollision(py::module_& m);  // CollisionObject, CollisionRequest, CollisionResult, collide
void bindManager(py::module_& m);    // CollisionManager, ObjectContact
void bindBatch(py::module_& m);      // collide_batch, collide_poses, BatchResult
// recode.conformance: the conformance suite (recode/conformance/*.hpp) for Python back ends
void bindConformance(py::module_& m);
// recode.devices(): devices.hpp
void bindReprs(py::module_& m);  // __repr__ where a class above has none; bound last

}  // namespace recode::python
