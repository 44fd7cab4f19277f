// The simulation's device pool (core/sim/src/device_pool.hpp): without a factory, a new frame
// size reshapes a CpuDevice that no test of the frame runs on (set aside, or held for an idle
// size) instead of making one, never one of a size the frame has tests of; with a factory
// every device is the factory's.

#include <catch2/catch.hpp>

#include <memory>
#include <utility>
#include <vector>

#include "device_pool.hpp"
#include "recode/raster/cpu_device.hpp"

using namespace recode;
using namespace recode::core;

namespace {

const raster::CpuDevice& cpu(raster::DepthStencilDevice& device) {
  return dynamic_cast<const raster::CpuDevice&>(device);
}

}  // namespace

TEST_CASE("a new frame size reshapes an idle CpuDevice, never a busy one", "[pool]") {
  DevicePool pool({});
  pool.trim({{64, 32}});
  pool.reserve(64, 32, 2);
  raster::DepthStencilDevice* first = &pool.at(64, 32, 0);
  first->clearStencil(7);  // as a pair test leaves it

  // Next frame: one new size; 64x32 is idle, so one of its devices is reshaped.
  pool.trim({{40, 40}});
  pool.reserve(40, 40, 1);
  raster::DepthStencilDevice& reused = pool.at(40, 40, 0);
  CHECK((&reused == first || &reused == &pool.at(64, 32, 0)));
  CHECK(pool.held(64, 32) == 1);
  CHECK(reused.width() == 40);
  CHECK(reused.height() == 40);
  const raster::CpuDevice fresh(40, 40);
  CHECK(std::vector(cpu(reused).stencilBuffer().begin(), cpu(reused).stencilBuffer().end()) ==
        std::vector(fresh.stencilBuffer().begin(), fresh.stencilBuffer().end()));

  // A frame with 40x40 and a new size: 40x40 is busy, 64x32 idle and taken.
  raster::DepthStencilDevice* idle = &pool.at(64, 32, 0);
  pool.trim({{40, 40}, {8, 8}});
  pool.reserve(40, 40, 1);
  pool.reserve(8, 8, 1);
  CHECK(&pool.at(40, 40, 0) == &reused);
  CHECK(&pool.at(8, 8, 0) == idle);
  CHECK(pool.held(64, 32) == 0);

  // Nothing idle: a new device.
  pool.trim({{40, 40}, {8, 8}, {16, 16}});
  pool.reserve(16, 16, 1);
  raster::DepthStencilDevice& made = pool.at(16, 16, 0);
  CHECK(&made != &reused);
  CHECK(&made != idle);
}

TEST_CASE("the idle device reshaped is the one that holds the size with least memory", "[pool]") {
  DevicePool pool({});
  pool.trim({{100, 100}, {10, 10}, {30, 20}});
  for (const auto& [w, h] : {std::pair{100, 100}, std::pair{10, 10}, std::pair{30, 20}})
    pool.reserve(w, h, 1);
  raster::DepthStencilDevice* middle = &pool.at(30, 20, 0);
  pool.trim({{20, 20}});
  pool.reserve(20, 20, 1);
  CHECK(&pool.at(20, 20, 0) == middle);
  CHECK(pool.held(30, 20) == 0);
  CHECK(pool.held(100, 100) == 1);
  CHECK(pool.held(10, 10) == 1);
}

TEST_CASE("with a factory every device is made by it", "[pool]") {
  int made = 0;
  DevicePool pool([&made](int w, int h) -> std::unique_ptr<raster::DepthStencilDevice> {
    ++made;
    return std::make_unique<raster::CpuDevice>(w, h);
  });
  pool.trim({{64, 32}});
  pool.reserve(64, 32, 1);
  pool.trim({{40, 40}});
  pool.reserve(40, 40, 1);
  CHECK(made == 2);
  CHECK(pool.held(64, 32) == 1);
}

TEST_CASE("a size the frame did not list keeps its own devices while it grows", "[pool]") {
  DevicePool pool({});
  pool.trim({});
  pool.reserve(32, 32, 1);
  pool.reserve(32, 32, 3);  // takes nothing from itself: three devices, not a loop
  CHECK(pool.held(32, 32) == 3);
}
