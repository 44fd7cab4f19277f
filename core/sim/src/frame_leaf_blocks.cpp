#include "frame_leaf_blocks.hpp"

namespace recode::core {

void FrameLeafBlocks::start() {
  // A frame that stopped before make() leaves made_ as the frame before it made it.
  for (auto& [key, block] : made_)
    if (block)
      kept_[key] = std::move(block);
  made_.clear();
  slots_.clear();
  keys_.clear();
}

std::size_t FrameLeafBlocks::need(int object, int leaf) {
  const auto [entry, added] = slots_.try_emplace({object, leaf}, keys_.size());
  if (added)
    keys_.emplace_back(object, leaf);
  return entry->second;
}

void FrameLeafBlocks::make(const std::vector<ObjectTree>& objects, PairTestRunner& runner) {
  made_.clear();
  made_.reserve(keys_.size());
  for (const Key& key : keys_) {
    const auto kept = kept_.find(key);
    made_.emplace_back(key, kept == kept_.end() ? nullptr : std::move(kept->second));
  }
  kept_.clear();
  runner.forEach(made_.size(), [&](std::size_t i) {
    auto& [key, block] = made_[i];
    const ObjectTree& tree = objects[static_cast<std::size_t>(key.first)];
    if (block)
      block->moveTo(tree, key.second);
    else
      block = std::make_unique<LeafBlock>(tree, key.second);
  });
}

}  // namespace recode::core
