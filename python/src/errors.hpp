#pragma once
// The Python exceptions the module raises that pybind11 has no C++ type for.

#include <pybind11/pybind11.h>

#include <cerrno>
#include <string>

namespace recode::python {

namespace py = pybind11;

// Raises FileNotFoundError(message).
[[noreturn]] inline void fileNotFound(const std::string& message) {
  PyErr_SetString(PyExc_FileNotFoundError, message.c_str());
  throw py::error_already_set();
}

// Raises FileNotFoundError(ENOENT, message, path), as open() does: str() is "[Errno 2] MESSAGE:
// 'PATH'" and the exception's filename is the path.
[[noreturn]] inline void fileNotFound(const std::string& message, const std::string& path) {
  const py::object error =
      py::module_::import("builtins").attr("FileNotFoundError")(ENOENT, message, path);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  throw py::error_already_set();
}

}  // namespace recode::python
