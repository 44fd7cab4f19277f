// collidePairs: record every pair's passes, run them once, conclude each pair.
#include "recode/pair/pair_batch.hpp"

#include <optional>
#include <stdexcept>
#include <utility>

#include "recode/raster/pending_read.hpp"

#include "block_window_source.hpp"
#include "pair_passes.hpp"
#include "pair_stages.hpp"

namespace recode::core {

namespace {

using detail::Clock;
using detail::microsecondsSince;

// What a recorded pair waits for: its read-backs, and what concluding it needs.
struct RecordedPair {
  PairResult result;
  std::optional<OrthoView> view;  // set when the passes were recorded
  raster::PendingRead<std::uint8_t> stencil;
  raster::PendingRead<std::uint32_t> nearDepth;  // waiting only with the contact passes
  raster::PendingRead<std::uint32_t> farDepth;
  double ownUs = 0.0;  // recording and concluding, without the wait
};

void requireBlocks(const PairJob& job, std::size_t index) {
  if (job.a == nullptr || job.b == nullptr)
    throw std::invalid_argument("collidePairs: job " + std::to_string(index) + " has no block " +
                                (job.a == nullptr ? "A" : "B"));
}

// Records the pair's passes and read-backs; what collidePair does before its first read-back,
// then the contact passes over the MOR without waiting for the verdict.
RecordedPair recordPair(raster::DepthStencilDevice& device, const PairJob& job) {
  const Clock::time_point start = Clock::now();
  const FrameSpec& frame = job.request.frame;
  detail::requireDeviceSize(device, frame);
  RecordedPair p{detail::startPair(*job.a, *job.b, frame), {}, {}, {}, {}, 0.0};
  PairResult& r = p.result;
  const OrthoView view = detail::pairView(frame, r);
  const detail::BlockWindowSource sourceA(*job.a, view), sourceB(*job.b, view);
  if (detail::choosePassRegion(detail::DrawnPair{sourceA, sourceB}, job.request, r)) {
    p.view = view;
    detail::PassRunner passes(device, sourceA, sourceB);
    detail::StepRunner steps(device, nullptr, r.timing);
    detail::recordStencilPasses(passes, steps, r.mor);
    steps.run(PairStep::ReadStencil, [&] { p.stencil = device.readStencilLater(r.mor); });
    if (job.request.contact) {
      steps.run(PairStep::ContactNear, [&] {
        passes.overlapEnd(r.mor, true);
        p.nearDepth = device.readDepthLater(r.mor);
      });
      steps.run(PairStep::ContactFar, [&] {
        passes.overlapEnd(r.mor, false);
        p.farDepth = device.readDepthLater(r.mor);
      });
    }
  }
  p.ownUs = microsecondsSince(start);
  return p;
}

// The rest of collidePair, from the read-backs.
PairResult concludePair(RecordedPair& p, const PairJob& job, double waitShareUs) {
  const Clock::time_point start = Clock::now();
  PairResult& r = p.result;
  if (p.view) {
    const raster::PixelBuffer<std::uint8_t> stencil{r.mor, p.stencil.take()};
    const raster::PixelRect contactRect = detail::concludeStencil(stencil, *p.view, r);
    if (r.collide && job.request.contact) {
      r.contactRect = contactRect;
      const raster::PixelBuffer<std::uint32_t> nearDepth{r.mor, p.nearDepth.take()};
      const raster::PixelBuffer<std::uint32_t> farDepth{r.mor, p.farDepth.take()};
      detail::concludeContact(nearDepth, farDepth, *p.view, *job.a, *job.b, job.request, r);
    }
  }
  r.timing.totalUs = p.ownUs + waitShareUs + microsecondsSince(start);
  return std::move(r);
}

}  // namespace

std::vector<PairResult> collidePairs(raster::DepthStencilDevice& device,
                                     std::span<const PairJob> jobs) {
  for (std::size_t i = 0; i < jobs.size(); ++i)
    requireBlocks(jobs[i], i);
  std::vector<PairResult> results;
  results.reserve(jobs.size());
  if (!device.defers()) {
    for (const PairJob& job : jobs)
      results.push_back(collidePair(device, *job.a, *job.b, job.request));
    return results;
  }
  std::vector<RecordedPair> recorded;
  recorded.reserve(jobs.size());
  try {
    for (const PairJob& job : jobs)
      recorded.push_back(recordPair(device, job));
  } catch (...) {
    device.finish();  // runs what was recorded, so the device is left with nothing pending
    throw;
  }
  const Clock::time_point wait = Clock::now();
  device.finish();
  std::size_t drawn = 0;
  for (const RecordedPair& p : recorded)
    drawn += p.view ? 1 : 0;
  const double waitShareUs = drawn > 0 ? microsecondsSince(wait) / static_cast<double>(drawn) : 0.0;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    results.push_back(concludePair(recorded[i], jobs[i], recorded[i].view ? waitShareUs : 0.0));
  return results;
}

}  // namespace recode::core
