#pragma once
// The devices Python draws on, by the names of the device registry ("cpu", "gl", "gl-exact",
// "vulkan", "vulkan-32", "vulkan-compute", "vulkan-native"). The module has the devices whose
// packages its build found (cmake/gpu_devices.cmake), whether built with the project's CMake or
// by `pip install .`; recode.devices() says why any other is missing.

#include <pybind11/pybind11.h>

#include <string>

#include "recode/api/device_pool.hpp"

namespace recode::python {

namespace py = pybind11;

// The pool of the named device, made on first use and kept for the module's life (devices of
// GPU APIs are warmed up once, on first use of a frame size). Throws std::invalid_argument (a
// ValueError) for a name the registry does not know or a device this module lacks, saying why.
DevicePool& devicePool(const std::string& name);

// A factory for CollisionManager: empty for "cpu"; throws as devicePool.
core::DeviceFactory deviceFactory(const std::string& name);

void bindDevices(py::module_& m);  // recode.devices()

}  // namespace recode::python
