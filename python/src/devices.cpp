#include "devices.hpp"

#include <map>
#include <stdexcept>

#include "recode/backends/device_registry.hpp"

namespace recode::python {

namespace {

// What to do for a device this module lacks: the registry's words, which end "and reconfigure",
// and for a module that pip built, how to build it again.
std::string missingReason(const backends::DeviceInfo& d) {
  if (d.built)
    return "";
  std::string why = "not in this module: " + std::string(d.missing);
#if RECODE_PYTHON_PIP
  why += " (for this module: run `pip install --no-build-isolation .` again)";
#endif
  return why;
}

}  // namespace

core::DeviceFactory deviceFactory(const std::string& name) {
  const backends::DeviceKind kind = backends::parseDeviceKind(name);
  const backends::DeviceInfo& info = backends::deviceInfo(kind);
  if (!info.built)
    throw std::invalid_argument("device \"" + name + "\": " + missingReason(info));
  try {
    return backends::deviceFactoryFor(kind);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

SharedPool& devicePool(const std::string& name) {
  // Leaked on purpose: GPU-API devices share process-wide contexts that must outlive them, and
  // Python gives no order of destruction at exit. A std::map: its entries never move.
  static auto& pools = *new std::map<std::string, SharedPool>();
  auto it = pools.find(name);
  if (it == pools.end())
    it = pools.try_emplace(name, DevicePool(deviceFactory(name))).first;
  return it->second;
}

void bindDevices(py::module_& m) {
  m.def(
      "devices",
      [] {
        py::list list;
        for (const backends::DeviceInfo& d : backends::deviceRegistry()) {
          py::dict entry;
          entry["name"] = std::string(d.name);
          entry["description"] = std::string(d.description);
          entry["exact"] = d.exact;
          entry["available"] = d.built;
          entry["missing"] = missingReason(d);
          list.append(entry);
        }
        return list;
      },
      "The devices collide() and CollisionManager can draw on, every one of the registry: a list "
      "of dicts with name, description, exact (gives the CPU reference's bits), available (built "
      "into this module) and missing (why not and what to install when not available, else "
      "\"\").");
}

}  // namespace recode::python
