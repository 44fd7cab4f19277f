#pragma once
// `recode explain SCENE --frame K --pair NAME_A:NAME_B`: one block pair of a scene whose
// objects are trees of blocks, posed at frame K and drawn in the frame `recode run` gives it,
// with the box descent that led (or did not lead) to it.

#include <string>

#include "pair/pair_setup.hpp"
#include "recode/pair/frame.hpp"

namespace recode::explain {

struct HierarchyPair {
  PairSetup setup;
  std::string descentHtml;  // the box-descent section's text and table
};

// NAME_A and NAME_B are blocks (leaves) of the scene's objects, by path ("dumbbell/bar") or,
// when only one block has it, by name. Throws std::invalid_argument naming --pair or --frame,
// the value and the rule; core::SceneError for the file.
[[nodiscard]] HierarchyPair hierarchyPair(const std::string& scenePath, int frame,
                                          const std::string& pairSpec,
                                          const core::FrameOverrides& overrides);

}  // namespace recode::explain
