// collidePairs: record every pair's passes, run them at once, conclude each pair.
#include "recode/pair/pair_batch.hpp"

#include <algorithm>
#include <functional>
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

// One stretch of a pair's commands: draws, then the read-back of what they left (or the
// keeping of a depth for a summary).
struct Segment {
  std::function<void()> draw;
  std::function<void()> read;
};

// A pair of the batch while it waits for its read-backs.
struct RecordedPair {
  const PairJob* job = nullptr;
  raster::DepthStencilDevice* device = nullptr;
  ContactSchedule schedule = ContactSchedule::AfterVerdict;
  PairResult result;
  std::optional<OrthoView> view;  // set by preparePair
  bool drawn = false;             // whether the passes are recorded (the box test and MOR let them)
  // The blocks as drawn, kept only while passes are still to be recorded.
  std::unique_ptr<detail::BlockWindowSource> a, b;
  std::vector<Segment> segments;  // the commands of the round being recorded, in order
  // With a summary (usesSummary), the device's reduction of the stencil and contact depths;
  // else the stencil and depths themselves.
  raster::PendingRead<raster::PixelSummary> summary;
  std::shared_ptr<const raster::KeptDepth> nearEnd;  // between a summary's two segments
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

// Whether the pair is concluded from summaries of the device's buffers (pixel_summary.hpp)
// rather than from the buffers: when the request leaves the pixels out and asks for no normal
// (the normal needs every pixel's ends).
bool usesSummary(const PairRequest& request) {
  return !request.keepPixels && !(request.contact && request.normal);
}

// Runs `body` as `step` of the pair's timing, on its device.
template <class Body>
void step(RecordedPair& p, PairStep which, Body&& body) {
  detail::StepRunner(*p.device, nullptr, p.result.timing).run(which, std::forward<Body>(body));
}

// The stencil passes over `rect` (the MOR, or in a summarised pair's second round its contact
// rectangle).
void drawStencilPasses(RecordedPair& p, const raster::PixelRect& rect) {
  detail::PassRunner passes(*p.device, *p.a, *p.b);
  detail::StepRunner steps(*p.device, nullptr, p.result.timing);
  detail::recordStencilPasses(passes, steps, rect);
}

// One contact pass (the near or the far end) over `rect`.
void drawContactPass(RecordedPair& p, const raster::PixelRect& rect, bool nearEnd) {
  step(p, nearEnd ? PairStep::ContactNear : PairStep::ContactFar,
       [&] { detail::PassRunner(*p.device, *p.a, *p.b).overlapEnd(rect, nearEnd); });
}

// Both contact passes over `rect`, each followed by its depth read-back: two segments.
void addContactSegments(RecordedPair& p, const raster::PixelRect& rect) {
  p.depthRect = rect;
  p.segments.push_back({[&p, rect] { drawContactPass(p, rect, true); },
                        [&p, rect] {
                          step(p, PairStep::ContactNear,
                               [&] { p.nearDepth = p.device->readDepthLater(rect); });
                        }});
  p.segments.push_back({[&p, rect] { drawContactPass(p, rect, false); },
                        [&p, rect] {
                          step(p, PairStep::ContactFar,
                               [&] { p.farDepth = p.device->readDepthLater(rect); });
                        }});
}

// What collidePair does before it draws: the pair's depth range, view and blocks as drawn, the
// box test and the MOR.
RecordedPair preparePair(raster::DepthStencilDevice& device, const PairJob& job,
                         ContactSchedule schedule) {
  const Clock::time_point start = Clock::now();
  const FrameSpec& frame = job.request.frame;
  detail::requireDeviceSize(device, frame);
  RecordedPair p;
  p.job = &job;
  p.device = &device;
  p.schedule = schedule;
  p.result = detail::startPair(*job.a, *job.b, frame);
  p.view = detail::pairView(frame, p.result);
  p.a = std::make_unique<detail::BlockWindowSource>(*job.a, *p.view);
  p.b = std::make_unique<detail::BlockWindowSource>(*job.b, *p.view);
  p.drawn = detail::choosePassRegion(detail::DrawnPair{*p.a, *p.b}, job.request, p.result);
  p.ownUs = microsecondsSince(start);
  return p;
}

// The stencil passes over `rect` and its summary; `withContact`: both contact passes over `rect`
// between them, the near end kept on the device, and their depths in the summary (the contact
// passes leave the stencil as the stencil passes made it: stencil write mask 0). Over a
// contact rectangle inside the MOR the stencil passes leave the MOR's values (a pass's value
// at a pixel does not depend on the scissor), so the summary's depths are the MOR's.
void addSummarySegments(RecordedPair& p, const raster::PixelRect& rect, bool withContact) {
  if (!withContact) {
    p.segments.push_back({[&p, rect] { drawStencilPasses(p, rect); },
                          [&p, rect] {
                            step(p, PairStep::ReadStencil, [&] {
                              p.summary =
                                  p.device->summarizeLater(rect, detail::caseClasses(), nullptr);
                            });
                          }});
    return;
  }
  p.segments.push_back({[&p, rect] {
                          drawStencilPasses(p, rect);
                          drawContactPass(p, rect, true);
                        },
                        [&p, rect] {
                          step(p, PairStep::ContactNear,
                               [&] { p.nearEnd = p.device->keepDepthLater(rect); });
                        }});
  p.segments.push_back({[&p, rect] { drawContactPass(p, rect, false); },
                        [&p, rect] {
                          step(p, PairStep::ReadStencil, [&] {
                            p.summary = p.device->summarizeLater(rect, detail::caseClasses(),
                                                                 p.nearEnd.get());
                          });
                          p.nearEnd.reset();
                        }});
}

// The first round's segments of a pair preparePair found drawn (its address is kept by them):
// what collidePair does before its first read-back, read-backs recorded instead of waited for.
// The stencil passes and the stencil's read-back, with ContactSchedule::Speculative the contact
// passes over the MOR too; or, concluded from summaries, the stencil passes and their summary,
// speculatively with the contact passes and their depths.
void addFirstRound(RecordedPair& p) {
  const raster::PixelRect mor = p.result.mor;
  const PairRequest& request = p.job->request;
  const bool speculative = request.contact && p.schedule == ContactSchedule::Speculative;
  if (usesSummary(request)) {
    addSummarySegments(p, mor, speculative);
    return;
  }
  p.segments.push_back({[&p, mor] { drawStencilPasses(p, mor); },
                        [&p, mor] {
                          step(p, PairStep::ReadStencil,
                               [&] { p.stencil = p.device->readStencilLater(mor); });
                        }});
  if (speculative)
    addContactSegments(p, mor);
}

// Records the segments of `pairs`. Pairs on devices of their own form a wave: the wave's first
// segments are drawn, pair after pair, then read, then its second segments, and so on, so a
// device with a recording of its own needs a barrier only between a wave's draws and its reads
// (vulkan_recorder.hpp). A pair whose device an earlier pair of the wave used starts the next
// wave, so every device sees each of its pairs' commands whole and in order, as collidePair
// gives them.
void recordInWaves(const std::vector<RecordedPair*>& pairs) {
  std::size_t first = 0;
  while (first < pairs.size()) {
    std::vector<const raster::DepthStencilDevice*> used;
    std::size_t last = first;
    for (; last < pairs.size(); ++last) {
      if (std::find(used.begin(), used.end(), pairs[last]->device) != used.end())
        break;
      used.push_back(pairs[last]->device);
    }
    for (std::size_t k = 0;; ++k) {
      bool any = false;
      for (std::size_t i = first; i < last; ++i) {
        RecordedPair& p = *pairs[i];
        if (k >= p.segments.size())
          continue;
        any = true;
        const Clock::time_point start = Clock::now();
        p.segments[k].draw();
        p.ownUs += microsecondsSince(start);
      }
      if (!any)
        break;
      for (std::size_t i = first; i < last; ++i) {
        RecordedPair& p = *pairs[i];
        if (k >= p.segments.size())
          continue;
        const Clock::time_point start = Clock::now();
        p.segments[k].read();
        p.ownUs += microsecondsSince(start);
      }
    }
    for (std::size_t i = first; i < last; ++i)
      pairs[i]->segments.clear();
    first = last;
  }
}

// The verdict from the stencil or its summary, and from a summary with the speculative contact
// passes' depths the contact region too. Returns whether the pair still needs its contact
// passes' depths.
bool concludeStencil(RecordedPair& p) {
  if (!p.drawn)
    return false;
  const Clock::time_point start = Clock::now();
  PairResult& r = p.result;
  raster::PixelRect contactRect;
  std::optional<raster::DepthIntervals> depth;
  if (usesSummary(p.job->request)) {
    const raster::PixelSummary summary = p.summary.take().front();
    contactRect = detail::concludeSummary(summary, *p.view, r);
    depth = summary.depth;
  } else {
    const raster::PixelBuffer<std::uint8_t> stencil{r.mor, p.stencil.take()};
    contactRect = detail::concludeStencil(stencil, *p.view, r);
  }
  const bool contact = r.collide && p.job->request.contact;
  if (contact)
    r.contactRect = contactRect;
  if (contact && depth)
    detail::concludeSummaryContact(*depth, *p.view, r);
  p.ownUs += microsecondsSince(start);
  return contact && !depth;
}

void concludeContact(RecordedPair& p) {
  const Clock::time_point start = Clock::now();
  if (usesSummary(p.job->request)) {
    const raster::PixelSummary summary = p.summary.take().front();
    // Over the contact rectangle: its marked pixels are the MOR's interfering ones.
    detail::concludeSummaryContact(*summary.depth, *p.view, p.result);
    p.ownUs += microsecondsSince(start);
    return;
  }
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
  recorded.reserve(jobs.size());  // never reallocated: the segments hold the pairs' addresses
  try {
    for (std::size_t i = 0; i < jobs.size(); ++i)
      recorded.push_back(preparePair(*devices[i], jobs[i], schedule));
    std::vector<RecordedPair*> drawn;
    for (RecordedPair& p : recorded) {
      if (p.drawn) {
        addFirstRound(p);
        drawn.push_back(&p);
      }
    }
    recordInWaves(drawn);
    for (RecordedPair& p : recorded) {
      // Only contact passes recorded after the verdict draw the blocks again.
      if (!(p.drawn && p.job->request.contact && schedule == ContactSchedule::AfterVerdict)) {
        p.a.reset();
        p.b.reset();
      }
    }
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
      for (RecordedPair* p : touching) {
        if (usesSummary(p->job->request))
          addSummarySegments(*p, p->result.contactRect, true);
        else
          addContactSegments(*p, p->result.contactRect);
      }
      recordInWaves(touching);
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
