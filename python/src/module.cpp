// The Python module `recode` (docs/api.md#python): RECODE's collision API with NumPy arrays.
// Errors: core::MeshError (a block that is not a valid convex block, a closed mesh that is not
// a valid closed mesh, a malformed mesh file)
// becomes recode.MeshError, a ValueError; the API's std::invalid_argument a ValueError (both
// pybind11's defaults and ours keep the C++ message); bad arrays a ValueError or TypeError
// naming the argument (arrays.cpp).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "devices.hpp"
#include "recode/geometry/mesh_error.hpp"

PYBIND11_MODULE(recode, m) {
  m.doc() =
      "RECODE image-based collision detection (Baciu, Wong, Sun 1999) for convex blocks and "
      "closed meshes: blocks and meshes from NumPy arrays or mesh files, objects at poses, "
      "collide() and a CollisionManager. See docs/api.md.";
  m.attr("__version__") = RECODE_VERSION;
  pybind11::register_exception<recode::core::MeshError>(m, "MeshError", PyExc_ValueError);
  recode::python::bindGeometry(m);
  recode::python::bindCollision(m);
  recode::python::bindManager(m);
  recode::python::bindBatch(m);
  recode::python::bindDevices(m);
  recode::python::bindConformance(m);
  recode::python::bindReprs(m);
}
