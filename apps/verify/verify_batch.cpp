// checkBatch: the input's pairs as one collidePairs batch on a GPU device, against the reference.
#include "verify/verify_batch.hpp"

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "recode/pair/pair_batch.hpp"
#include "recode/pair/pair_result_compare.hpp"

namespace recode::app {

BatchCheck checkBatch(const std::vector<BatchPair>& pairs, const core::DeviceFactory& factory) {
  const auto start = std::chrono::steady_clock::now();
  BatchCheck check;
  std::vector<core::PairBlock> blocks;
  blocks.reserve(2 * pairs.size());
  std::map<std::pair<int, int>, std::unique_ptr<raster::DepthStencilDevice>> bySize;
  std::vector<raster::DepthStencilDevice*> devices;
  std::vector<core::PairJob> jobs;
  for (const BatchPair& p : pairs) {
    // With hierarchies and object-space meshes: the devices that cull, and those that run the
    // vertex stage themselves (posed draws), take their own paths.
    blocks.push_back(core::PairBlock::withHierarchy(*p.a));
    blocks.push_back(core::PairBlock::withHierarchy(*p.b));
    const core::FrameSpec& frame = p.request.frame;
    auto& device = bySize[{frame.width, frame.height}];
    if (!device)
      device = factory(frame.width, frame.height);
    devices.push_back(device.get());
    jobs.push_back({&blocks[blocks.size() - 2], &blocks.back(), p.request});
  }
  const std::vector<core::PairResult> results = core::collidePairs(devices, jobs);
  for (std::size_t i = 0; i < results.size(); ++i) {
    ++check.pairs;
    const std::optional<std::string> difference =
        core::firstDifference(results[i], *pairs[i].reference);
    if (!difference)
      continue;
    if (check.different++ == 0)
      check.firstDifferent = *pairs[i].label + ": " + *difference;
  }
  for (const auto& [size, device] : bySize) {
    const raster::TransferCounters t = device->transfers();
    check.submissions += t.submissions;
    check.readbackBytes += t.readbackBytes;
  }
  check.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return check;
}

}  // namespace recode::app
