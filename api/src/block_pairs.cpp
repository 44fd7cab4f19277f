// Planning, deciding and merging the block pairs of collide() and the manager.
#include "block_pairs.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "layered_pairs.hpp"
#include "recode/pair/pair_batch.hpp"
#include "recode/refine/adaptive.hpp"
#include "recode/refine/proven_apart.hpp"

namespace recode::detail {

namespace {

// Adds one block pair's contact region to the object pair's.
void mergeContact(core::ContactRegion& into, const core::ContactRegion& from) {
  into.points.insert(into.points.end(), from.points.begin(), from.points.end());
  into.box.extend(from.box);
  into.pixels += from.pixels;
  into.area += from.area;
  into.maxDepth = std::max(into.maxDepth, from.maxDepth);
  into.collapsedPixels += from.collapsedPixels;
}

// One block pair in the request's mode.
BlockPairAnswer decideOne(raster::DepthStencilDevice& device, const PlannedBlockPair& p,
                          core::PairMode mode) {
  BlockPairAnswer out;
  out.frame = p.request.frame;
  if (p.layered) {
    out.layered = core::collideLayered(device, p.blockA.block, p.blockB.block, p.request);
    out.pair = pairResultOf(*out.layered);
    return out;
  }
  if (mode == core::PairMode::Reference || mode == core::PairMode::SkipApart) {
    out.pair = core::collidePair(device, p.blockA.block, p.blockB.block, p.request);
    return out;
  }
  if (mode == core::PairMode::Conservative) {
    out.pair =
        core::collideConservative(device, p.blockA.block.mesh(), p.blockB.block.mesh(), p.request)
            .pair;
    return out;
  }
  thread_local core::AdaptivePairTester tester;
  core::AdaptiveResult r = tester.collide(device, p.blockA.block, p.blockB.block, p.request);
  out.atLimit = r.verdict == core::PairVerdict::ApartAtLimit;
  if (r.contact) {
    out.pair = std::move(*r.contact);
    out.frame = r.contactFrame;
    out.level = r.contactLevel;
  } else if (r.reference) {
    out.pair = std::move(*r.reference);
  }
  out.pair.collide = r.verdict == core::PairVerdict::Collide;
  return out;
}

// The pool holds at most this many sizes at once (a new size past it empties the pool), so a
// batch asks it for at most this many: every device of a batch stays alive until it is done.
constexpr std::size_t kSizesPerBatch = 16;

}  // namespace

PlannedBlockPair::PlannedBlockPair(const CollisionObject& a, const CollisionObject& b, int leafA,
                                   int leafB, core::PairRequest pairRequest)
    : blockA(a.tree(), leafA),
      blockB(b.tree(), leafB),
      request(std::move(pairRequest)),
      objectBlockA(static_cast<std::size_t>(a.geometry().blockOfNode(leafA))),
      objectBlockB(static_cast<std::size_t>(b.geometry().blockOfNode(leafB))) {}

std::size_t BlockPairPlan::add(const CollisionObject& a, const CollisionObject& b,
                               const CollisionRequest& request, CollisionResult& result) {
  result.clear();
  if (request.threads < 0)
    throw std::invalid_argument("CollisionRequest::threads is " + std::to_string(request.threads) +
                                ": give 1 (the caller's thread), 0 (every hardware thread) or "
                                "a count");
  const bool layered = isLayeredPair(a, b);
  if (layered) {
    requireLayeredRequest(a, b, request);
    result.layered.emplace();
  }
  firstOfObjectPair_.push_back(pairs_.size());
  std::vector<core::LeafPair> leafPairs;
  result.boxTests = core::descendPair(a.tree(), b.tree(), leafPairs);
  for (const core::LeafPair& lp : leafPairs) {
    const core::HierarchyNode& na = a.tree().nodes()[static_cast<std::size_t>(lp.leafA)];
    const core::HierarchyNode& nb = b.tree().nodes()[static_cast<std::size_t>(lp.leafB)];
    core::PairRequest pair;
    pair.frame = chooseFrame(na.worldAabb, nb.worldAabb, request);
    pair.mor = request.mor;
    pair.contact = request.contact;
    pair.normal = request.normal;
    // Proven apart from the leaves' own meshes and poses: no world mesh is made for a skipped
    // pair.
    if (request.mode == core::PairMode::SkipApart &&
        core::provenApart(core::PosedBlock{na.localMesh, na.world, na.worldAabb, na.localExtent},
                          core::PosedBlock{nb.localMesh, nb.world, nb.worldAabb, nb.localExtent},
                          pair.frame)) {
      ++result.blockPairsSkipped;
      continue;
    }
    pairs_.emplace_back(a, b, lp.leafA, lp.leafB, std::move(pair)).layered = layered;
  }
  return firstOfObjectPair_.size() - 1;
}

std::vector<BlockPairAnswer> BlockPairPlan::decide(core::PairMode mode, DevicePool& devices,
                                                   int threads, double* setupUs) const {
  std::vector<BlockPairAnswer> answers(pairs_.size());
  if (devices.makesCpuDevices() && threads != 1 && pairs_.size() > 1) {
    decideOnThreads(mode, threads, answers, setupUs);
    return answers;
  }
  const struct AddSetup {
    const DevicePool& pool;
    double before;
    double* sum;
    ~AddSetup() {
      if (sum)
        *sum += pool.setupUs() - before;
    }
  } addSetup{devices, devices.setupUs(), setupUs};
  const bool batched = mode == core::PairMode::Reference || mode == core::PairMode::SkipApart;
  if (!batched) {
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
      const core::FrameSpec& f = pairs_[i].request.frame;
      answers[i] = decideOne(devices.device(f.width, f.height), pairs_[i], mode);
    }
    return answers;
  }
  // Layered pairs on their own (collidePairs batches RECODE's passes), then batches of at most
  // kSizesPerBatch frame sizes of the others, in plan order.
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const core::FrameSpec& f = pairs_[i].request.frame;
    if (pairs_[i].layered)
      answers[i] = decideOne(devices.device(f.width, f.height), pairs_[i], mode);
  }
  for (std::size_t first = 0; first < pairs_.size();) {
    std::map<std::pair<int, int>, raster::DepthStencilDevice*> sizes;
    std::vector<core::PairJob> jobs;
    std::vector<raster::DepthStencilDevice*> batchDevices;
    std::vector<std::size_t> slots;  // the plan index of each job
    std::size_t end = first;
    for (; end < pairs_.size(); ++end) {
      const PlannedBlockPair& p = pairs_[end];
      if (p.layered)
        continue;
      const std::pair<int, int> size{p.request.frame.width, p.request.frame.height};
      auto found = sizes.find(size);
      if (found == sizes.end()) {
        if (sizes.size() == kSizesPerBatch)
          break;
        found = sizes.emplace(size, &devices.device(size.first, size.second)).first;
      }
      jobs.push_back({&p.blockA.block, &p.blockB.block, p.request});
      batchDevices.push_back(found->second);
      slots.push_back(end);
    }
    std::vector<core::PairResult> results = core::collidePairs(batchDevices, jobs);
    for (std::size_t k = 0; k < results.size(); ++k) {
      answers[slots[k]].pair = std::move(results[k]);
      answers[slots[k]].frame = pairs_[slots[k]].request.frame;
    }
    first = end;
  }
  return answers;
}

void BlockPairPlan::decideOnThreads(core::PairMode mode, int threads,
                                    std::vector<BlockPairAnswer>& answers, double* setupUs) const {
  const int concurrency = threads > 0 ? std::min(threads, tbb::info::default_concurrency())
                                      : tbb::info::default_concurrency();
  std::vector<std::exception_ptr> errors(pairs_.size());
  std::vector<double> setup(pairs_.size(), 0.0);
  tbb::task_arena arena(concurrency);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, pairs_.size(), [&](std::size_t i) {
      // CPU devices of this thread's own (a device is used by one thread at a time); which
      // device of a size decides a pair changes nothing in its answer.
      thread_local DevicePool cpuDevices;
      try {
        const core::FrameSpec& f = pairs_[i].request.frame;
        const double before = cpuDevices.setupUs();
        raster::DepthStencilDevice& device = cpuDevices.device(f.width, f.height);
        setup[i] = cpuDevices.setupUs() - before;
        answers[i] = decideOne(device, pairs_[i], mode);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
  });
  for (const std::exception_ptr& error : errors)  // the first in plan order, as in turn
    if (error)
      std::rethrow_exception(error);
  if (setupUs)
    for (const double us : setup)
      *setupUs += us;
}

void BlockPairPlan::merge(std::size_t index, std::vector<BlockPairAnswer>& answers,
                          CollisionResult& result) const {
  const std::size_t first = firstOfObjectPair_.at(index);
  const std::size_t end =
      index + 1 < firstOfObjectPair_.size() ? firstOfObjectPair_[index + 1] : pairs_.size();
  for (std::size_t i = first; i < end; ++i) {
    BlockPairAnswer& answer = answers[i];
    core::PairResult& r = answer.pair;
    ++result.blockPairsDrawn;
    result.apartAtLimit += answer.atLimit ? 1 : 0;
    if (answer.layered)  // the one block pair of a layered object pair
      result.layered = LayeredPair{answer.frame, std::move(*answer.layered)};
    if (!r.collide)
      continue;
    result.collide = true;
    result.interferingPixels += r.interferingPixels;
    mergeContact(result.contact, r.contact);
    result.contacts.push_back({pairs_[i].objectBlockA, pairs_[i].objectBlockB, answer.frame,
                               std::move(r), answer.level, pairs_[i].layered});
  }
}

}  // namespace recode::detail
