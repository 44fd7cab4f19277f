// collidePairs: record every pair's passes, run them at once, conclude each pair.
#include "recode/pair/pair_batch.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "recode/raster/pending_read.hpp"

#include "block_window_source.hpp"
#include "pair_passes.hpp"
#include "pair_stages.hpp"

namespace recode::core {

namespace {

using detail::Clock;
using detail::microsecondsSince;

// A pair of the batch while it waits for its read-backs.
struct RecordedPair {
  const PairJob* job = nullptr;
  raster::DepthStencilDevice* device = nullptr;
  ContactSchedule schedule = ContactSchedule::AfterVerdict;
  PairResult result;
  std::optional<OrthoView> view;  // set when the passes were recorded
  // The blocks as drawn, kept only while contact passes may still be recorded after the verdict.
  std::unique_ptr<detail::BlockWindowSource> a, b;
  // With a summary (usesSummary), the device's reduction of the stencil and contact depths;
  // else the stencil and depths themselves.
  raster::PendingRead<raster::PixelSummary> summary;
  raster::PendingRead<std::uint8_t> stencil;
  raster::PendingRead<std::uint32_t> nearDepth;  // waiting only with the contact passes
  raster::PendingRead<std::uint32_t> farDepth;
  raster::PixelRect depthRect;  // what the depths were read over
  double ownUs = 0.0;           // recording and concluding, without the waits
};

void requireBlocks(const PairJob& job, std::size_t index) {
  if (job.a == nullptr || job.b == nullptr)
    throw std::invalid_argument("collidePairs: job " + std::to_string(index) + " has no block " +
                                (job.a == nullptr ? "A" : "B"));
}

// Both contact passes over `rect`, each with its depth read-back recorded.
void recordContactPasses(raster::DepthStencilDevice& device, RecordedPair& p,
                         const raster::PixelRect& rect) {
  detail::PassRunner passes(device, *p.a, *p.b);
  detail::StepRunner steps(device, nullptr, p.result.timing);
  p.depthRect = rect;
  steps.run(PairStep::ContactNear, [&] {
    passes.overlapEnd(rect, true);
    p.nearDepth = device.readDepthLater(rect);
  });
  steps.run(PairStep::ContactFar, [&] {
    passes.overlapEnd(rect, false);
    p.farDepth = device.readDepthLater(rect);
  });
}

// Whether the pair is concluded from a summary of the device's buffers (pixel_summary.hpp)
// rather than from the buffers: when the request leaves the pixels out and the contact, if
// asked for, is measured in the same submission (its normal needs every pixel's ends).
bool usesSummary(const PairRequest& request, ContactSchedule schedule) {
  if (request.keepPixels)
    return false;
  return !request.contact || (!request.normal && schedule == ContactSchedule::Speculative);
}

// The stencil passes, then (with the contact) both contact passes over the MOR, the near
// ends kept on the device, and the summary of the stencil and of both ends: the contact passes
// leave the stencil as the stencil passes made it (stencil write mask 0).
void recordSummarizedPair(raster::DepthStencilDevice& device, RecordedPair& p,
                          detail::PassRunner& passes, detail::StepRunner& steps) {
  const raster::PixelRect mor = p.result.mor;
  std::shared_ptr<const raster::KeptDepth> nearEnd;
  if (p.job->request.contact) {
    steps.run(PairStep::ContactNear, [&] {
      passes.overlapEnd(mor, true);
      nearEnd = device.keepDepthLater(mor);
    });
    steps.run(PairStep::ContactFar, [&] { passes.overlapEnd(mor, false); });
  }
  steps.run(PairStep::ReadStencil,
            [&] { p.summary = device.summarizeLater(mor, detail::caseClasses(), nearEnd.get()); });
}

// What collidePair does before its first read-back, the read-back recorded instead of waited
// for; with ContactSchedule::Speculative, the contact passes over the MOR too.
RecordedPair recordPair(raster::DepthStencilDevice& device, const PairJob& job,
                        ContactSchedule schedule) {
  const Clock::time_point start = Clock::now();
  const FrameSpec& frame = job.request.frame;
  detail::requireDeviceSize(device, frame);
  RecordedPair p;
  p.job = &job;
  p.device = &device;
  p.schedule = schedule;
  p.result = detail::startPair(*job.a, *job.b, frame);
  PairResult& r = p.result;
  const OrthoView view = detail::pairView(frame, r);
  p.a = std::make_unique<detail::BlockWindowSource>(*job.a, view);
  p.b = std::make_unique<detail::BlockWindowSource>(*job.b, view);
  if (detail::choosePassRegion(detail::DrawnPair{*p.a, *p.b}, job.request, r)) {
    p.view = view;
    detail::PassRunner passes(device, *p.a, *p.b);
    detail::StepRunner steps(device, nullptr, r.timing);
    detail::recordStencilPasses(passes, steps, r.mor);
    if (usesSummary(job.request, schedule)) {
      recordSummarizedPair(device, p, passes, steps);
    } else {
      steps.run(PairStep::ReadStencil, [&] { p.stencil = device.readStencilLater(r.mor); });
      if (job.request.contact && schedule == ContactSchedule::Speculative)
        recordContactPasses(device, p, r.mor);
    }
  }
  // Only contact passes recorded after the verdict draw the blocks again.
  if (!(p.view && job.request.contact && schedule == ContactSchedule::AfterVerdict &&
        !usesSummary(job.request, schedule))) {
    p.a.reset();
    p.b.reset();
  }
  p.ownUs = microsecondsSince(start);
  return p;
}

// The verdict from the stencil. Returns whether the pair needs its contact passes' depths.
bool concludeStencil(RecordedPair& p) {
  if (!p.view)
    return false;
  const Clock::time_point start = Clock::now();
  PairResult& r = p.result;
  if (usesSummary(p.job->request, p.schedule)) {
    // The verdict and, with the contact, the contact region: nothing left to read.
    detail::concludeSummary(p.summary.take().front(), *p.view, r);
    p.ownUs += microsecondsSince(start);
    return false;
  }
  const raster::PixelBuffer<std::uint8_t> stencil{r.mor, p.stencil.take()};
  const raster::PixelRect contactRect = detail::concludeStencil(stencil, *p.view, r);
  const bool contact = r.collide && p.job->request.contact;
  if (contact)
    r.contactRect = contactRect;
  p.ownUs += microsecondsSince(start);
  return contact;
}

void concludeContact(RecordedPair& p) {
  const Clock::time_point start = Clock::now();
  const raster::PixelBuffer<std::uint32_t> nearDepth{p.depthRect, p.nearDepth.take()};
  const raster::PixelBuffer<std::uint32_t> farDepth{p.depthRect, p.farDepth.take()};
  detail::concludeContact(nearDepth, farDepth, *p.view, *p.job->a, *p.job->b, p.job->request,
                          p.result);
  p.ownUs += microsecondsSince(start);
}

// Finishes every device of the batch, each once, in the order the jobs first used them (devices
// that share one recording, as the Vulkan devices of a process do, run it all at the first).
void finishAll(std::span<raster::DepthStencilDevice* const> devices) {
  std::vector<raster::DepthStencilDevice*> finished;
  for (raster::DepthStencilDevice* device : devices) {
    if (std::find(finished.begin(), finished.end(), device) != finished.end())
      continue;
    device->finish();
    finished.push_back(device);
  }
}

// Runs what is recorded; the wait is shared equally by `sharers` pairs.
void finishShared(std::span<raster::DepthStencilDevice* const> devices,
                  std::vector<RecordedPair*> sharers) {
  const Clock::time_point wait = Clock::now();
  finishAll(devices);
  if (sharers.empty())
    return;
  const double share = microsecondsSince(wait) / static_cast<double>(sharers.size());
  for (RecordedPair* p : sharers)
    p->ownUs += share;
}

}  // namespace

std::vector<PairResult> collidePairs(raster::DepthStencilDevice& device,
                                     std::span<const PairJob> jobs, ContactSchedule schedule) {
  const std::vector<raster::DepthStencilDevice*> devices(jobs.size(), &device);
  return collidePairs(devices, jobs, schedule);
}

std::vector<PairResult> collidePairs(std::span<raster::DepthStencilDevice* const> devices,
                                     std::span<const PairJob> jobs, ContactSchedule schedule) {
  if (devices.size() != jobs.size())
    throw std::invalid_argument("collidePairs: " + std::to_string(jobs.size()) + " jobs but " +
                                std::to_string(devices.size()) + " devices");
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    requireBlocks(jobs[i], i);
    if (devices[i] == nullptr)
      throw std::invalid_argument("collidePairs: job " + std::to_string(i) + " has no device");
  }
  std::vector<PairResult> results;
  results.reserve(jobs.size());
  const bool defer = std::all_of(devices.begin(), devices.end(),
                                 [](const raster::DepthStencilDevice* d) { return d->defers(); });
  if (!defer) {
    for (std::size_t i = 0; i < jobs.size(); ++i)
      results.push_back(collidePair(*devices[i], *jobs[i].a, *jobs[i].b, jobs[i].request));
    return results;
  }
  std::vector<RecordedPair> recorded;
  recorded.reserve(jobs.size());
  try {
    for (std::size_t i = 0; i < jobs.size(); ++i)
      recorded.push_back(recordPair(*devices[i], jobs[i], schedule));
    std::vector<RecordedPair*> drawn;
    for (RecordedPair& p : recorded)
      if (p.view)
        drawn.push_back(&p);
    finishShared(devices, drawn);
    std::vector<RecordedPair*> touching;
    for (RecordedPair* p : drawn) {
      if (concludeStencil(*p)) {
        touching.push_back(p);
      } else {
        p->a.reset();  // drawn no more
        p->b.reset();
      }
    }
    if (schedule == ContactSchedule::AfterVerdict) {
      for (RecordedPair* p : touching)
        recordContactPasses(*p->device, *p, p->result.contactRect);
      finishShared(devices, touching);
    }
    for (RecordedPair* p : touching)
      concludeContact(*p);
  } catch (...) {
    finishAll(devices);  // runs what was recorded, so no device is left with anything pending
    throw;
  }
  for (RecordedPair& p : recorded) {
    detail::dropPixelsUnlessKept(p.job->request, p.result);
    p.result.timing.totalUs = p.ownUs;
    results.push_back(std::move(p.result));
  }
  return results;
}

}  // namespace recode::core
