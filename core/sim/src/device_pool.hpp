#pragma once
// The simulation's devices: per frame size, as many as the frame's pair tests can use at once
// (one on the sequential path). They are all made before the frame's pair tests start, on the
// calling thread, so that making them is timed apart from the tests (FrameReport's
// deviceSetupUs) and a device is never made while another thread draws; the tests then borrow
// one each and give it back.

#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::core {

class DevicePool {
 public:
  // An empty factory makes raster::CpuDevice.
  explicit DevicePool(DeviceFactory factory) : factory_(std::move(factory)) {}

  // Drops the devices of sizes not in `keep` once more than kKeptSizes sizes are held, so a
  // run whose pairs keep changing size stays bounded.
  void trim(const std::vector<std::pair<int, int>>& keep);

  // Makes devices of this size until `count` exist; returns the microseconds spent making.
  // Not thread-safe: call it before the frame's pair tests start.
  double reserve(int width, int height, int count);

  // A device of this size not lent to anyone else; reserve() must have made enough.
  // Thread-safe with release().
  [[nodiscard]] raster::DepthStencilDevice& borrow(int width, int height);
  void release(raster::DepthStencilDevice& device);

  static constexpr std::size_t kKeptSizes = 16;

 private:
  struct Devices {
    std::vector<std::unique_ptr<raster::DepthStencilDevice>> owned;
    std::vector<raster::DepthStencilDevice*> idle;
  };

  DeviceFactory factory_;
  std::map<std::pair<int, int>, Devices> bySize_;
  std::mutex mutex_;  // guards every Devices::idle during the pair tests
};

}  // namespace recode::core
