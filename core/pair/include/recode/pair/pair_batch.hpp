#pragma once
// A frame's pair tests as one batch. On a device that runs commands as they come (the CPU
// reference) the batch is collidePair on each pair in turn. On a device that defers its
// commands (raster::DepthStencilDevice::defers: the Vulkan device) every pair's passes and
// read-backs are recorded first and run in one submission, then each pair is concluded from
// its read-backs: the GPU waits for the host once a batch instead of three times a pair.

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

// Result i is collidePair(device, *jobs[i].a, *jobs[i].b, jobs[i].request), field for field
// but for the timing. On a deferring device the contact passes run, over the MOR, for every
// pair whose passes run and whose request asks for contact, before anyone knows whether the
// pair interferes: a pixel's depth after a pass does not depend on the scissor the pass ran
// under, so the contact rectangle's depths read from the MOR are the ones collidePair reads,
// and pairs found apart simply ignore theirs. The timing on a deferring device: the steps
// are the recording of each pass, and totalUs adds to the pair's own recording and
// conclusion an equal share of the wait for the submission. Throws what collidePair throws;
// on a deferring device nothing is run before every job has been checked and recorded, and an
// error leaves the device finished (no commands pending).
[[nodiscard]] std::vector<PairResult> collidePairs(raster::DepthStencilDevice& device,
                                                   std::span<const PairJob> jobs);

}  // namespace recode::core
