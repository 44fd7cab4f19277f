// Devices per frame size, made ahead of the pair tests.
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

int DevicePool::held(int width, int height) const {
  const auto it = bySize_.find({width, height});
  return it == bySize_.end() ? 0 : static_cast<int>(it->second.made.size());
}

long long DevicePool::uses(int width, int height) const {
  const auto it = bySize_.find({width, height});
  return it == bySize_.end() ? 0 : it->second.uses;
}

void DevicePool::addUses(int width, int height, long long tests) {
  bySize_[{width, height}].uses += tests;
}

double DevicePool::reserve(int width, int height, int count) {
  auto& devices = bySize_[{width, height}].made;
  double us = 0.0;
  while (static_cast<int>(devices.size()) < count) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<raster::DepthStencilDevice> device =
        factory_ ? factory_(width, height) : std::make_unique<raster::CpuDevice>(width, height);
    if (!device)
      throw std::logic_error("the run's device factory returned no device");
    us +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    devices.push_back(std::move(device));
  }
  return us;
}

raster::DepthStencilDevice& DevicePool::at(int width, int height, int index) {
  return *bySize_.at({width, height}).made.at(static_cast<std::size_t>(index));
}

}  // namespace recode::core
