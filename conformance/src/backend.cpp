#include "recode/conformance/backend.hpp"

#include <utility>

#include "recode/kit/reference_model.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::conformance {

std::string_view toString(BackendFailure f) {
  switch (f) {
    case BackendFailure::Crashed:
      return "crashed";
    case BackendFailure::TimedOut:
      return "timed out";
    case BackendFailure::Flooded:
      return "flooded";
    case BackendFailure::Malformed:
      return "malformed";
  }
  return "?";
}

DeviceBackend::DeviceBackend(std::string name, DeviceFactory factory)
    : name_(std::move(name)), factory_(std::move(factory)) {}

Answer DeviceBackend::run(const raster::CommandStream& stream) {
  const std::unique_ptr<raster::DepthStencilDevice> device = factory_(stream.width, stream.height);
  Answer a;
  try {
    raster::replay(stream.commands, *device);
  } catch (const std::invalid_argument& e) {
    a.refused = e.what();
    if (a.refused.empty())
      a.refused = "refused (no reason given)";
    return a;
  }
  const raster::PixelRect all{0, 0, stream.width, stream.height};
  a.depth = device->readDepth(all);
  a.stencil = device->readStencil(all);
  return a;
}

ModelBackend::ModelBackend(kit::Variant variant) : variant_(variant) {}

std::string ModelBackend::name() const {
  return variant_ == kit::Variant::Contract
             ? "reference model"
             : "reference model, " + std::string(kit::variantName(variant_));
}

Answer ModelBackend::run(const raster::CommandStream& stream) {
  kit::ReferenceModel model(stream.width, stream.height, variant_);
  Answer a;
  try {
    model.run(stream.commands);
  } catch (const std::invalid_argument& e) {
    a.refused = e.what();
    return a;
  }
  a.depth = model.depthBuffer();
  a.stencil = model.stencilBuffer();
  return a;
}

Answer referenceAnswer(const raster::CommandStream& stream) {
  raster::CpuDevice device(stream.width, stream.height);
  raster::replay(stream.commands, device);
  Answer a;
  a.depth.assign(device.depthBuffer().begin(), device.depthBuffer().end());
  a.stencil.assign(device.stencilBuffer().begin(), device.stencilBuffer().end());
  return a;
}

}  // namespace recode::conformance
