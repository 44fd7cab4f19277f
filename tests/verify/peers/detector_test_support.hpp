#pragma once
// What the suites of the bench's detectors (RECODE's and the peers') share: the object trees
// of a scene, and the checks every detection must pass whatever the detector.

#include <catch2/catch.hpp>

#include <vector>

#include "recode/scene/scene.hpp"
#include "recode/sim/hierarchy.hpp"
#include "recode/verify/scene_detector.hpp"

namespace recode::test {

inline std::vector<core::ObjectTree> treesOf(const core::Scene& scene) {
  std::vector<core::ObjectTree> trees;
  for (const core::SceneObject& object : scene.objects)
    trees.emplace_back(object);
  return trees;
}

// Every reported pair joins two different objects in order and names a leaf of each.
inline void checkPairsAreLeafPairs(const std::vector<core::ObjectTree>& trees,
                                   const std::vector<verify::LeafPairId>& pairs) {
  const auto isLeaf = [&](int object, int node) {
    return trees[static_cast<std::size_t>(object)].nodes()[static_cast<std::size_t>(node)].isLeaf();
  };
  for (const verify::LeafPairId& p : pairs) {
    CHECK(p.objectA < p.objectB);
    CHECK(isLeaf(p.objectA, p.leafA));
    CHECK(isLeaf(p.objectB, p.leafB));
  }
}

}  // namespace recode::test
