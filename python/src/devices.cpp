#include "devices.hpp"

#include <map>
#include <stdexcept>

#if RECODE_PYTHON_HAVE_BACKENDS
#include "recode/backends/device_registry.hpp"
#endif

namespace recode::python {

core::DeviceFactory deviceFactory(const std::string& name) {
#if RECODE_PYTHON_HAVE_BACKENDS
  const backends::DeviceKind kind = backends::parseDeviceKind(name);
  try {
    return backends::deviceFactoryFor(kind);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
#else
  if (name == "cpu")
    return {};
  throw std::invalid_argument(
      "device \"" + name +
      "\": this module has the cpu device only (built with the libraries alone, as `pip "
      "install .` builds it); build it with the project's CMake (scripts/build.sh) for the "
      "GPU back ends");
#endif
}

DevicePool& devicePool(const std::string& name) {
  // Leaked on purpose: GPU-API devices share process-wide contexts that must outlive them, and
  // Python gives no order of destruction at exit.
  static auto& pools = *new std::map<std::string, DevicePool>();
  auto it = pools.find(name);
  if (it == pools.end())
    it = pools.emplace(name, DevicePool(deviceFactory(name))).first;
  return it->second;
}

void bindDevices(py::module_& m) {
  m.def(
      "devices",
      [] {
        py::list list;
#if RECODE_PYTHON_HAVE_BACKENDS
        for (const backends::DeviceInfo& d : backends::deviceRegistry()) {
          py::dict entry;
          entry["name"] = std::string(d.name);
          entry["description"] = std::string(d.description);
          entry["exact"] = d.exact;
          entry["available"] = d.built;
          list.append(entry);
        }
#else
        py::dict entry;
        entry["name"] = "cpu";
        entry["description"] = "the CPU reference (raster::CpuDevice): the contract's bits";
        entry["exact"] = true;
        entry["available"] = true;
        list.append(entry);
#endif
        return list;
      },
      "The devices collide() and CollisionManager can draw on: a list of dicts with name, "
      "description, exact (gives the CPU reference's bits) and available (in this module).");
}

}  // namespace recode::python
