#pragma once
// The devices Python draws on, by the names of the device registry ("cpu", "gl", "gl-exact",
// "vulkan", "vulkan-32", "vulkan-compute", "vulkan-native"). The module has the devices whose
// packages its build found (cmake/gpu_devices.cmake), whether built with the project's CMake or
// by `pip install .`; recode.devices() says why any other is missing.

#include <pybind11/pybind11.h>

#include <mutex>
#include <string>
#include <utility>

#include "recode/api/device_pool.hpp"

namespace recode::python {

namespace py = pybind11;

// A device's pool, shared by every Python thread that names the device, and the lock a query
// holds while it draws on it (a device draws for one thread at a time). Take the lock only
// without the GIL (after py::gil_scoped_release), so that no thread waits for it while holding
// the GIL; taking the GIL back while holding it is allowed.
struct SharedPool {
  explicit SharedPool(DevicePool p) : pool(std::move(p)) {}
  DevicePool pool;
  std::mutex mutex;
};

// The pool of the named device, made on first use and kept for the module's life (devices of
// GPU APIs are warmed up once, on first use of a frame size). Throws std::invalid_argument (a
// ValueError) for a name the registry does not know or a device this module lacks, saying why.
// Call it with the GIL held (the GIL guards the table of pools).
SharedPool& devicePool(const std::string& name);

// A factory for CollisionManager: empty for "cpu"; throws as devicePool.
core::DeviceFactory deviceFactory(const std::string& name);

void bindDevices(py::module_& m);  // recode.devices()

}  // namespace recode::python
