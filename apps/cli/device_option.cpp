#include "cli/device_option.hpp"

namespace recode::app {

namespace {

// CLI11's own message for a bad value names only the option; the registry's names the choices.
const CLI::Validator kDeviceName(
    [](std::string& text) -> std::string {
      try {
        (void)backends::parseDeviceKind(text);
        return "";
      } catch (const std::invalid_argument& e) {
        return e.what();
      }
    },
    "NAME");

}  // namespace

std::string deviceChoices() {
  std::string text;
  for (const backends::DeviceInfo& d : backends::deviceRegistry()) {
    text += (text.empty() ? "" : "; ") + std::string(d.name) + ": " + std::string(d.description);
    if (!d.built)
      text += " (not in this build: " + std::string(d.missing) + ")";
  }
  return text;
}

CLI::Option* addDeviceOption(CLI::App& cmd, std::string& name, const std::string& what) {
  return cmd.add_option("--device", name, what + ": " + deviceChoices())
      ->check(kDeviceName)
      ->capture_default_str();
}

std::unique_ptr<raster::DepthStencilDevice> makeNamedDevice(const std::string& name, int width,
                                                            int height) {
  return backends::makeDevice(backends::parseDeviceKind(name), width, height);
}

core::DeviceFactory namedDeviceFactory(const std::string& name) {
  return backends::deviceFactoryFor(backends::parseDeviceKind(name));
}

}  // namespace recode::app
