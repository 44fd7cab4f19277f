#pragma once
// The simulation's devices, by frame size: one per size on the sequential path, and with
// threads up to one per test of that size that can run at once. They are made before the
// frame's pair tests start, on the calling thread, so that making them is timed apart from the
// tests (FrameReport's deviceSetupUs) and no device is made while another thread draws.

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::core {

class DevicePool {
 public:
  // An empty factory makes raster::CpuDevice.
  explicit DevicePool(DeviceFactory factory) : factory_(std::move(factory)) {}

  // Starts a frame whose tests have the sizes in `keep`. Drops the devices of other sizes once
  // more than kKeptSizes sizes are held, so a run whose pairs keep changing size stays
  // bounded; without a factory those CpuDevices are set aside (up to kKeptSizes) for reuse.
  void trim(const std::vector<std::pair<int, int>>& keep);

  // Devices of this size held now, and pair tests they ran since they were made.
  [[nodiscard]] int held(int width, int height) const;
  [[nodiscard]] long long uses(int width, int height) const;
  void addUses(int width, int height, long long tests);

  // Makes devices of this size until `count` exist; returns the microseconds spent making.
  // Without a factory a device is a CpuDevice set aside or held for a size this frame has no
  // test of, reshaped (the one with the least memory that holds the size, else the largest),
  // and only when there is none a new one: a frame's pairs change size as their blocks move,
  // and making a device maps its buffers' pages anew, which costs far more than clearing them.
  double reserve(int width, int height, int count);

  // What the devices held now have handed to hardware and back since they were made.
  [[nodiscard]] raster::TransferCounters transfers() const;

  // Some device held now (the first of the smallest size), or null when none is.
  [[nodiscard]] const raster::DepthStencilDevice* anyHeld() const;

  // Device `index` (below reserve's count) of this size.
  [[nodiscard]] raster::DepthStencilDevice& at(int width, int height, int index);

  static constexpr std::size_t kKeptSizes = 16;

 private:
  struct Devices {
    std::vector<std::unique_ptr<raster::DepthStencilDevice>> made;
    long long uses = 0;
  };

  // A CpuDevice of this size from spare_ or an idle size's devices, or a new one.
  std::unique_ptr<raster::DepthStencilDevice> reuseOrMakeCpuDevice(int width, int height);

  DeviceFactory factory_;
  std::map<std::pair<int, int>, Devices> bySize_;
  std::vector<std::pair<int, int>> frameSizes_;                     // the last trim's `keep`
  std::vector<std::unique_ptr<raster::DepthStencilDevice>> spare_;  // CpuDevices of dropped sizes
};

}  // namespace recode::core
