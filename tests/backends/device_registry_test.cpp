// The device registry: every kind once, names that parse back, devices made at the size asked,
// and for a kind this build lacks an error that says what to install.

#include <catch2/catch.hpp>

#include <set>
#include <stdexcept>
#include <string>

#include "recode/backends/device_registry.hpp"

using namespace recode;

TEST_CASE("every registered device has a name that parses back to its kind", "[registry]") {
  std::set<std::string> names;
  for (const backends::DeviceInfo& d : backends::deviceRegistry()) {
    INFO(d.name);
    CHECK(backends::parseDeviceKind(d.name) == d.kind);
    CHECK(backends::toString(d.kind) == d.name);
    CHECK(&backends::deviceInfo(d.kind) == &d);
    CHECK_FALSE(d.description.empty());
    CHECK((d.built || !d.missing.empty()));
    names.insert(std::string(d.name));
  }
  CHECK(names == std::set<std::string>{"cpu", "gl", "gl-exact", "vulkan", "vulkan-32",
                                       "vulkan-compute", "vulkan-native"});
  // The promise of the reference's bits: every device but the native ones (fixed-function GL,
  // Vulkan's own rasterizer and depth).
  CHECK(backends::deviceInfo(backends::DeviceKind::Cpu).exact);
  CHECK_FALSE(backends::deviceInfo(backends::DeviceKind::Gl).exact);
  CHECK(backends::deviceInfo(backends::DeviceKind::GlExact).exact);
  CHECK(backends::deviceInfo(backends::DeviceKind::Vulkan).exact);
  CHECK(backends::deviceInfo(backends::DeviceKind::Vulkan32).exact);
  CHECK(backends::deviceInfo(backends::DeviceKind::VulkanCompute).exact);
  CHECK_FALSE(backends::deviceInfo(backends::DeviceKind::VulkanNative).exact);
  CHECK_THROWS_WITH(backends::parseDeviceKind("metal"),
                    "unknown device \"metal\" (devices: cpu, gl, gl-exact, vulkan, vulkan-32, "
                    "vulkan-compute, vulkan-native)");
}

TEST_CASE("a registered device is made at the size asked, or refused naming what to install",
          "[registry]") {
  for (const backends::DeviceInfo& d : backends::deviceRegistry()) {
    INFO(d.name);
    if (d.built) {
      const auto device = backends::makeDevice(d.kind, 24, 8);
      REQUIRE(device);
      CHECK(device->width() == 24);
      CHECK(device->height() == 8);
      const auto warm = backends::warmDeviceFactory(d.kind)(16, 16);
      REQUIRE(warm);
      CHECK(warm->width() == 16);
      // A run's factory: none for the CPU device (the run makes its own), the warm one else.
      const core::DeviceFactory forRun = backends::deviceFactoryFor(d.kind);
      CHECK(static_cast<bool>(forRun) == (d.kind != backends::DeviceKind::Cpu));
      if (forRun)
        CHECK(forRun(16, 16)->height() == 16);
    } else {
      CHECK_THROWS_WITH(backends::makeDevice(d.kind, 24, 8),
                        Catch::Contains(std::string(d.missing)));
      CHECK_THROWS_AS(backends::warmDeviceFactory(d.kind), std::runtime_error);
      CHECK_THROWS_AS(backends::deviceFactoryFor(d.kind), std::runtime_error);
    }
  }
  CHECK_THROWS_AS(backends::makeDevice(backends::DeviceKind::Cpu, 0, 8), std::invalid_argument);
}
