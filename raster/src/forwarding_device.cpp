#include "recode/raster/forwarding_device.hpp"

#include <stdexcept>
#include <utility>

namespace recode::raster {

ForwardingDevice::ForwardingDevice(std::unique_ptr<DepthStencilDevice> inner)
    : owned_(std::move(inner)), inner_(owned_.get()) {
  if (!inner_)
    throw std::invalid_argument("ForwardingDevice: no inner device");
}

}  // namespace recode::raster
