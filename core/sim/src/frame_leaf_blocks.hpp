#pragma once
// The leaves a frame's pair tests draw, each made ready once per frame (LeafBlock: world mesh,
// triangle hierarchy, pose) and kept for the next frame. A leaf drawn frame after frame is
// moved, not made again: no transform at all while its pose stays the same, else its world
// mesh rewritten in place, so that a run does not allocate, copy and map the pages of every
// drawn mesh anew each frame. Private to core::Simulation.

#include <cstddef>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "pair_tests.hpp"
#include "recode/sim/hierarchy.hpp"
#include "recode/sim/leaf_block.hpp"

namespace recode::core {

class FrameLeafBlocks {
 public:
  // A new frame: nothing listed yet; the last frame's blocks are kept until make().
  void start();

  // The slot of a leaf a pair test of this frame needs (the same slot for the same leaf).
  std::size_t need(int object, int leaf);

  // Makes every leaf listed ready at its object's current pose, on the runner's threads: a
  // leaf the last frame made is moved (LeafBlock::moveTo), another made anew. Leaves the last
  // frame made and this one does not list are let go, so what is kept is at most what one frame
  // draws. Rethrows the first error in listing order.
  void make(const std::vector<ObjectTree>& objects, PairTestRunner& runner);

  [[nodiscard]] const PairBlock* at(std::size_t slot) const { return &made_[slot].second->block; }

 private:
  using Key = std::pair<int, int>;  // object, leaf
  std::map<Key, std::size_t> slots_;
  std::vector<Key> keys_;  // per slot
  // This frame's blocks, per slot, once make() ran; at start() they become the kept ones.
  std::vector<std::pair<Key, std::unique_ptr<LeafBlock>>> made_;
  std::map<Key, std::unique_ptr<LeafBlock>> kept_;
};

}  // namespace recode::core
