#pragma once
// --device NAME, shared by `recode pair`, `recode run` and `recode conform`: a device of the
// registry (backends/registry), named as `recode conform --device` names it.

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "recode/backends/device_registry.hpp"
#include "recode/raster/device.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::app {

// The registry's devices for --help: each name, what it is, and what to install when this
// build lacks it.
[[nodiscard]] std::string deviceChoices();

// Adds --device to `cmd`, writing into `name` (which must outlive the parse; its value is the
// default). A name the registry does not know is refused by the parser, naming the choices.
CLI::Option* addDeviceOption(CLI::App& cmd, std::string& name, const std::string& what);

// A fresh width x height device of that name. Throws std::runtime_error naming the package
// to install when this build lacks it, or when no driver gives a context.
[[nodiscard]] std::unique_ptr<raster::DepthStencilDevice> makeNamedDevice(const std::string& name,
                                                                          int width, int height);

// For core::RunOptions::deviceFactory: backends::deviceFactoryFor the named kind (empty for
// "cpu", so the run keeps its own CPU devices and threads). Throws as makeNamedDevice when this
// build lacks the device.
[[nodiscard]] core::DeviceFactory namedDeviceFactory(const std::string& name);

}  // namespace recode::app
