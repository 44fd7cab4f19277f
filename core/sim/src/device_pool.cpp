// Devices per frame size, made ahead of the pair tests and lent to them one at a time.
#include "device_pool.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "recode/raster/cpu_device.hpp"

namespace recode::core {

void DevicePool::trim(const std::vector<std::pair<int, int>>& keep) {
  if (bySize_.size() <= kKeptSizes)
    return;
  std::erase_if(bySize_, [&](const auto& entry) {
    return std::find(keep.begin(), keep.end(), entry.first) == keep.end();
  });
}

double DevicePool::reserve(int width, int height, int count) {
  Devices& devices = bySize_[{width, height}];
  double us = 0.0;
  while (static_cast<int>(devices.owned.size()) < count) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<raster::DepthStencilDevice> device =
        factory_ ? factory_(width, height) : std::make_unique<raster::CpuDevice>(width, height);
    if (!device)
      throw std::logic_error("the run's device factory returned no device");
    us +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    devices.idle.push_back(device.get());
    devices.owned.push_back(std::move(device));
  }
  return us;
}

raster::DepthStencilDevice& DevicePool::borrow(int width, int height) {
  const std::lock_guard lock(mutex_);
  std::vector<raster::DepthStencilDevice*>& idle = bySize_.at({width, height}).idle;
  if (idle.empty())
    throw std::logic_error("more pair tests at once than devices reserved for their size");
  raster::DepthStencilDevice* device = idle.back();
  idle.pop_back();
  return *device;
}

void DevicePool::release(raster::DepthStencilDevice& device) {
  const std::lock_guard lock(mutex_);
  bySize_.at({device.width(), device.height()}).idle.push_back(&device);
}

}  // namespace recode::core
