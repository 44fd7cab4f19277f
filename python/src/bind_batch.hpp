#pragma once
// What the module's calls share to run without the GIL (docs/api.md#threads): a query copies
// what it reads of Python-owned objects while it holds the GIL, then releases it; a device pool
// shared between threads (recode.devices()' pools, one per device name) is locked while a query
// draws on it, since a device draws for one thread at a time.

#include <mutex>

#include "recode/api/device_pool.hpp"

namespace recode::python {

// The lock of the module's pool for a device other than "cpu". Take it only without the GIL
// (after py::gil_scoped_release), so that no thread waits for it while holding the GIL.
[[nodiscard]] std::mutex& poolMutex(const DevicePool& pool);

}  // namespace recode::python
