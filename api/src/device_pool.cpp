// Devices by frame size, made on first use through the user's factory or as CpuDevices.
#include "recode/api/device_pool.hpp"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "recode/raster/cpu_device.hpp"

namespace recode {

namespace {
// Above this many sizes the pool starts again, so that pairs of ever-changing sizes keep it
// bounded (as core::Simulation does with its devices).
constexpr std::size_t kMaxPooledSizes = 16;
}  // namespace

raster::DepthStencilDevice& DevicePool::device(int width, int height) {
  if (devices_.size() >= kMaxPooledSizes && !devices_.contains({width, height})) {
    if (!factory_)  // every device is then a CpuDevice
      for (auto& [size, device] : devices_)
        spare_.emplace_back(static_cast<raster::CpuDevice*>(device.release()));
    devices_.clear();
  }
  auto& slot = devices_[{width, height}];
  if (!slot) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<raster::DepthStencilDevice> made =
        factory_ ? factory_(width, height) : reuseOrMakeCpuDevice(width, height);
    setupUs_ +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    if (!made) {
      devices_.erase({width, height});
      throw std::logic_error("the device factory returned no device");
    }
    if (made->width() != width || made->height() != height) {
      devices_.erase({width, height});
      std::ostringstream m;
      m << "the device factory made a " << made->width() << "x" << made->height() << " device when "
        << width << "x" << height << " was asked for";
      throw std::invalid_argument(m.str());
    }
    slot = std::move(made);
  }
  return *slot;
}

std::unique_ptr<raster::DepthStencilDevice> DevicePool::reuseOrMakeCpuDevice(int width,
                                                                             int height) {
  std::vector<const raster::CpuDevice*> spares;
  for (const auto& device : spare_)
    spares.push_back(device.get());
  const std::size_t best = raster::bestDeviceToReshape(spares, width, height);
  if (best == spare_.size())
    return std::make_unique<raster::CpuDevice>(width, height);
  spare_[best]->reshape(width, height);
  std::unique_ptr<raster::DepthStencilDevice> device = std::move(spare_[best]);
  spare_.erase(spare_.begin() + static_cast<std::ptrdiff_t>(best));
  return device;
}

}  // namespace recode
