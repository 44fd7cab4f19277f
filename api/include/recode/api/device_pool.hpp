#pragma once
// The device seam of the collision API: where pairs are drawn. A DevicePool makes devices
// through a factory (core::DeviceFactory, the one `recode run` takes; empty: raster::CpuDevice,
// the reference) and keeps one per frame size, so that the collision calls that use it, frame
// after frame, make a device only for a size not seen before. Frames are sized in multiples of
// core::kPairFrameGranule pixels, so a few sizes serve most pairs.

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/device.hpp"
#include "recode/sim/simulation.hpp"

namespace recode {

// Devices by frame size, made on first use by a factory (the seam for a device of your own).
// Past 16 sizes the pool starts again; without a factory it keeps the CpuDevices it drops and
// reshapes them for the sizes that follow (raster::CpuDevice::reshape), instead of making new
// ones, whose buffers' pages the system would map anew.
class DevicePool {
 public:
  // `factory` makes a device of a given size; empty: raster::CpuDevice.
  explicit DevicePool(core::DeviceFactory factory = {}) : factory_(std::move(factory)) {}

  // The device of this size, made if new (its making timed into setupUs()). Throws
  // std::logic_error if the factory returns no device, std::invalid_argument if the device it
  // returns is not of the size asked for.
  [[nodiscard]] raster::DepthStencilDevice& device(int width, int height);

  // Microseconds spent making devices so far: a one-off cost, kept out of collision times.
  [[nodiscard]] double setupUs() const { return setupUs_; }
  // The number of devices made: one per frame size seen.
  [[nodiscard]] std::size_t size() const { return devices_.size(); }
  // Whether the pool makes raster::CpuDevices (it was given no factory).
  [[nodiscard]] bool makesCpuDevices() const { return !factory_; }

 private:
  // Without a factory: the spare CpuDevice best reshaped to this size, else a new one.
  std::unique_ptr<raster::DepthStencilDevice> reuseOrMakeCpuDevice(int width, int height);

  core::DeviceFactory factory_;
  std::map<std::pair<int, int>, std::unique_ptr<raster::DepthStencilDevice>> devices_;
  std::vector<std::unique_ptr<raster::CpuDevice>> spare_;  // dropped, to reshape
  double setupUs_ = 0.0;
};

}  // namespace recode
