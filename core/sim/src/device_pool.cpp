// Devices per frame size, made ahead of the pair tests.
#include "device_pool.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "recode/raster/cpu_device.hpp"

namespace recode::core {

void DevicePool::trim(const std::vector<std::pair<int, int>>& keep) {
  frameSizes_ = keep;
  if (bySize_.size() <= kKeptSizes)
    return;
  for (auto it = bySize_.begin(); it != bySize_.end();) {
    if (std::find(keep.begin(), keep.end(), it->first) != keep.end()) {
      ++it;
      continue;
    }
    if (!factory_)
      for (auto& device : it->second.made)
        if (spare_.size() < kKeptSizes)
          spare_.push_back(std::move(device));
    it = bySize_.erase(it);
  }
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
        factory_ ? factory_(width, height) : reuseOrMakeCpuDevice(width, height);
    if (!device)
      throw std::logic_error("the run's device factory returned no device");
    us +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    devices.push_back(std::move(device));
  }
  return us;
}

std::unique_ptr<raster::DepthStencilDevice> DevicePool::reuseOrMakeCpuDevice(int width,
                                                                             int height) {
  // Every device no test of this frame runs on: those set aside, and those of idle sizes (not
  // this one, even if the frame did not list it: reserve counts on its devices staying).
  std::vector<std::unique_ptr<raster::DepthStencilDevice>*> idle;
  for (auto& device : spare_)
    idle.push_back(&device);
  for (auto& [size, devices] : bySize_)
    if (size != std::pair{width, height} &&
        std::find(frameSizes_.begin(), frameSizes_.end(), size) == frameSizes_.end())
      for (auto& device : devices.made)
        idle.push_back(&device);
  std::vector<const raster::CpuDevice*> cpuDevices;
  for (const auto* device : idle)
    cpuDevices.push_back(static_cast<const raster::CpuDevice*>(device->get()));
  const std::size_t best = raster::bestDeviceToReshape(cpuDevices, width, height);
  if (best == idle.size())
    return std::make_unique<raster::CpuDevice>(width, height);
  static_cast<raster::CpuDevice&>(**idle[best]).reshape(width, height);
  std::unique_ptr<raster::DepthStencilDevice> device = std::move(*idle[best]);
  // The emptied slot leaves its list.
  std::erase(spare_, nullptr);
  for (auto& [size, devices] : bySize_)
    std::erase(devices.made, nullptr);
  return device;
}

const raster::DepthStencilDevice* DevicePool::anyHeld() const {
  for (const auto& [size, devices] : bySize_)
    if (!devices.made.empty())
      return devices.made.front().get();
  return nullptr;
}

raster::DepthStencilDevice& DevicePool::at(int width, int height, int index) {
  return *bySize_.at({width, height}).made.at(static_cast<std::size_t>(index));
}

raster::TransferCounters DevicePool::transfers() const {
  raster::TransferCounters sum;
  for (const auto& [size, devices] : bySize_) {
    for (const std::unique_ptr<raster::DepthStencilDevice>& device : devices.made) {
      sum += device->transfers();
    }
  }
  return sum;
}

}  // namespace recode::core
