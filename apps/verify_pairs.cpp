#include "verify_pairs.hpp"

#include "pair_setup.hpp"

#include "recode/sim/hierarchy.hpp"
#include "recode/verify/pair_suite.hpp"

namespace recode::app {

VerifyPairs scenePairs(const core::Scene& scene, const core::FrameOverrides& overrides, int frame) {
  if (scene.objects.size() < 2)
    throw core::SceneError(scene.sourceName, "objects",
                           "verifying needs at least two objects, the file has " +
                               std::to_string(scene.objects.size()));
  VerifyPairs out;
  out.source = scene.sourceName;
  std::vector<core::ObjectTree> trees;
  for (const core::SceneObject& object : scene.objects) {
    trees.emplace_back(object);
    trees.back().pose(frame);
  }
  for (std::size_t i = 0; i < trees.size(); ++i)
    for (std::size_t j = i + 1; j < trees.size(); ++j)
      for (const int leafA : trees[i].leaves())
        for (const int leafB : trees[j].leaves()) {
          PairToVerify p;
          p.label = trees[i].nodes()[static_cast<std::size_t>(leafA)].path + " / " +
                    trees[j].nodes()[static_cast<std::size_t>(leafB)].path;
          p.a = trees[i].worldMesh(leafA);
          p.b = trees[j].worldMesh(leafB);
          core::Aabb bounds = core::boundingBox(p.a);
          bounds.extend(core::boundingBox(p.b));
          p.frame = resolveFrameNamed(scene, bounds, overrides);
          out.pairs.push_back(std::move(p));
        }
  return out;
}

VerifyPairs suitePairs(int count, unsigned seed, int width) {
  verify::PairSuiteOptions options;
  options.count = count;
  options.seed = seed;
  options.width = width;
  VerifyPairs out;
  out.source = "generated suite (" + std::to_string(count) + " pairs, seed " +
               std::to_string(seed) + ", width " + std::to_string(width) + ")";
  for (verify::SuitePair& s : verify::generatePairSuite(options))
    out.pairs.push_back({std::move(s.label), std::move(s.a), std::move(s.b), s.frame});
  return out;
}

}  // namespace recode::app
