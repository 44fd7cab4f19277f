#pragma once
// A frame's pair tests as one batch. On a device that runs commands as they come (the CPU
// reference) the batch is collidePair on each pair in turn. On a device that defers its
// commands (raster::DepthStencilDevice::defers: the Vulkan device) every pair's passes and
// read-backs are recorded first and run in one submission, then each pair is concluded from
// its read-backs: the host waits for the GPU once or twice a batch (ContactSchedule) instead of
// up to three times a pair.
//
// A job whose request leaves the pixels out (PairRequest::keepPixels false) and asks for no
// normal is concluded from the device's summaries of its buffers
// (DepthStencilDevice::summarizeLater) instead of the buffers. The Vulkan device works them out
// in a compute shader, so such a pair test reads back 64 bytes (and 64 more for the contact
// of a pair that interferes, after the verdict).

#include <span>
#include <vector>

#include "recode/pair/pair.hpp"
#include "recode/pair/pair_block.hpp"

namespace recode::core {

// One pair test of a batch: the blocks (alive while the batch runs) and the request.
struct PairJob {
  const PairBlock* a = nullptr;
  const PairBlock* b = nullptr;
  PairRequest request;
};

// When a batch on a deferring device runs its contact passes.
enum class ContactSchedule {
  // In the one submission, over each drawn pair's MOR, before anyone knows whether the pair
  // interferes: a pixel's depth after a pass does not depend on the scissor the pass ran under,
  // so the contact rectangle's depths read from the MOR are those collidePair reads, and pairs
  // found apart ignore theirs. One submission a batch; every drawn pair pays both passes.
  Speculative,
  // In a second submission, over the contact rectangle of the pairs that interfere only, as
  // collidePair draws them. Two submissions a batch with contact; no pass is wasted.
  AfterVerdict,
};

// Result i is collidePair(device, *jobs[i].a, *jobs[i].b, jobs[i].request), field for field
// but for the timing. On a deferring device the timing's steps are the recording of each pass,
// and totalUs adds to the pair's own recording and concluding an equal share of each wait it
// took part in. Throws what collidePair throws, and std::invalid_argument for a job without a
// block; on a deferring device an error leaves the device finished (nothing pending).
[[nodiscard]] std::vector<PairResult> collidePairs(
    raster::DepthStencilDevice& device, std::span<const PairJob> jobs,
    ContactSchedule schedule = ContactSchedule::AfterVerdict);

// The same with job i on *devices[i] (a frame's pairs differ in frame size, and each size has
// its device). The batch defers when every device defers; each device is finished once per
// submission round, in the order the jobs first use them, so devices that share one recording
// (the Vulkan devices of a process) run the whole batch at once. Throws std::invalid_argument
// unless there is one device, not null, per job.
[[nodiscard]] std::vector<PairResult> collidePairs(
    std::span<raster::DepthStencilDevice* const> devices, std::span<const PairJob> jobs,
    ContactSchedule schedule = ContactSchedule::AfterVerdict);

}  // namespace recode::core
