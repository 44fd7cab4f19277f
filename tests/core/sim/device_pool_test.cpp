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

TEST_CASE("the pool keeps up to kKeptSizes sizes and sets aside up to kKeptSizes devices",
          "[pool]") {
  // kKeptSizes sizes (16), all in one frame, one device each, each 128 x (128 + i) pixels.
  const int kept = static_cast<int>(DevicePool::kKeptSizes);
  std::vector<std::pair<int, int>> sizes;
  for (int i = 0; i < kept; ++i)
    sizes.emplace_back(128, 128 + i);
  DevicePool pool({});
  pool.trim(sizes);
  for (const auto& [w, h] : sizes)
    pool.reserve(w, h, 1);
  // A frame with none of them: the pool holds exactly kKeptSizes sizes, no more, so it drops
  // nothing.
  pool.trim({{8, 8}});
  for (const auto& [w, h] : sizes)
    CHECK(pool.held(w, h) == 1);
  // One size more, in a frame with all the others (so no device is idle to reshape): a new
  // device, kKeptSizes + 1 sizes held. A frame with a new size then drops every held size but
  // the frame's, and sets aside at most kKeptSizes of their kKeptSizes + 1 CpuDevices.
  sizes.emplace_back(128, 128 + kept);
  pool.trim(sizes);
  pool.reserve(128, 128 + kept, 1);
  CHECK(pool.held(128, 128 + kept) == 1);
  pool.trim({{8, 8}});
  for (const auto& [w, h] : sizes)
    CHECK(pool.held(w, h) == 0);
  // A frame of kKeptSizes + 1 new small sizes: kKeptSizes of them get a device set aside
  // (reshaped, keeping its memory for at least 128 x 128 pixels), the last a new one.
  std::vector<std::pair<int, int>> small;
  for (int i = 0; i <= kept; ++i)
    small.emplace_back(8, 8 + i);
  pool.trim(small);
  int reused = 0;
  for (const auto& [w, h] : small) {
    pool.reserve(w, h, 1);
    reused += cpu(pool.at(w, h, 0)).pixelCapacity() >= 128 * 128 ? 1 : 0;
  }
  CHECK(reused == kept);
}

TEST_CASE("a size the pool holds no device for has no uses; reserving held devices takes no time",
          "[pool]") {
  DevicePool pool({});
  CHECK(pool.uses(16, 16) == 0);
  CHECK(pool.held(16, 16) == 0);
  pool.trim({{16, 16}});
  CHECK(pool.reserve(16, 16, 1) >= 0.0);
  pool.addUses(16, 16, 5);
  CHECK(pool.uses(16, 16) == 5);
  CHECK(pool.uses(32, 16) == 0);
  // Nothing is made, so nothing is timed: exactly zero microseconds.
  CHECK(pool.reserve(16, 16, 1) == 0.0);
  CHECK(pool.reserve(16, 16, 0) == 0.0);
}

TEST_CASE("anyHeld is null before any device and then the first device of the smallest size",
          "[pool]") {
  DevicePool pool({});
  CHECK(pool.anyHeld() == nullptr);
  pool.trim({{64, 64}, {32, 32}});
  pool.addUses(16, 16, 1);  // a size with uses but no device
  CHECK(pool.anyHeld() == nullptr);
  pool.reserve(64, 64, 1);
  pool.reserve(32, 32, 2);
  // Sizes in (width, height) order: 16 x 16 holds none, 32 x 32 is the first that holds one.
  CHECK(pool.anyHeld() == &pool.at(32, 32, 0));
}
