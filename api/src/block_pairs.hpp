#pragma once
// collide() in three steps, so that the manager can decide the block pairs of all its object
// pairs as one batch: plan (the descent, the frames, the skip-apart test), decide (every planned
// block pair, in the reference and skip-apart modes as core::collidePairs batches, which a
// deferring GPU device runs in one submission round), then merge each object pair's answers into
// its CollisionResult. The results are those of deciding the pairs one by one, in order. A pair
// with a closed mesh is one layered pair (core::collideLayered), decided on its own.

#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "recode/api/collision.hpp"
#include "recode/api/device_pool.hpp"
#include "recode/sim/leaf_block.hpp"

namespace recode::detail {

// One block pair to decide, and where its answer goes.
struct PlannedBlockPair {
  PlannedBlockPair(const CollisionObject& a, const CollisionObject& b, int leafA, int leafB,
                   core::PairRequest request);
  core::LeafBlock blockA;  // world meshes at the objects' poses
  core::LeafBlock blockB;
  core::PairRequest request;
  std::size_t objectBlockA = 0;  // the block's index in its object's geometry
  std::size_t objectBlockB = 0;
  bool layered = false;  // a closed mesh takes part: decided by core::collideLayered
};

// The answer for one block pair in the request's mode.
struct BlockPairAnswer {
  core::PairResult pair;
  core::FrameSpec frame;                           // the frame the answer was found in
  int level = 0;                                   // adaptive refinement level of that frame
  bool atLimit = false;                            // adaptive: apart at the refinement limit
  std::optional<core::LayeredPairResult> layered;  // the layered pair's answer (pair: its fields)
};

// The block pairs of a call (or a manager's frame), grouped by object pair. Stable addresses:
// a LeafBlock stays where it was made.
class BlockPairPlan {
 public:
  // Descends a and b, counts the box tests and skipped pairs into `result` (cleared first) and
  // plans the block pairs left. Returns the object pair's index in the plan.
  std::size_t add(const CollisionObject& a, const CollisionObject& b,
                  const CollisionRequest& request, CollisionResult& result);

  // Decides every planned block pair on the pool's devices; answers in plan order. With CPU
  // devices and `threads` other than 1 (CollisionRequest::threads), the pairs are decided on
  // that many oneTBB threads, each with CPU devices of its own, into their slots; the answers
  // are the same. Adds the time spent making devices to *setupUs.
  [[nodiscard]] std::vector<BlockPairAnswer> decide(core::PairMode mode, DevicePool& devices,
                                                    int threads, double* setupUs) const;

  // Merges object pair `index`'s answers (from decide) into its result.
  void merge(std::size_t index, std::vector<BlockPairAnswer>& answers,
             CollisionResult& result) const;

  [[nodiscard]] std::size_t blockPairs() const { return pairs_.size(); }

 private:
  void decideOnThreads(core::PairMode mode, int threads, std::vector<BlockPairAnswer>& answers,
                       double* setupUs) const;

  std::deque<PlannedBlockPair> pairs_;
  std::vector<std::size_t> firstOfObjectPair_;  // index into pairs_, one per add, then the end
};

}  // namespace recode::detail
