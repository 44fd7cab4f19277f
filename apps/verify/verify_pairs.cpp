#include "verify/verify_pairs.hpp"

#include "pair/pair_setup.hpp"

#include "recode/sim/hierarchy.hpp"
#include "recode/verify/pair_suite.hpp"

namespace recode::app {

VerifyPairs scenePairs(const core::Scene& scene, const core::FrameOverrides& overrides, int frame) {
  if (scene.objects.size() < 2)
    throw core::SceneError(scene.sourceName, "objects",
                           "verifying needs at least two objects, the file has " +
                               std::to_string(scene.objects.size()));
  // The judges of recode verify compare RECODE's passes with convex oracles.
  core::requireConvexBlocks(scene, "recode verify");
  VerifyPairs out;
  out.source = scene.sourceName;
  std::vector<core::ObjectTree> trees;
  for (const core::SceneObject& object : scene.objects) {
    trees.emplace_back(object);
    trees.back().pose(frame);
  }
  // Counted before any mesh is made: n blocks give n^2 / 2 pairs, and each pair is checked.
  long long pairs = 0, blocksBefore = 0;
  for (const core::ObjectTree& tree : trees) {
    const auto blocks = static_cast<long long>(tree.leaves().size());
    pairs += blocksBefore * blocks;
    blocksBefore += blocks;
    if (pairs > kMaxVerifiedPairs)
      throw core::SceneError(
          scene.sourceName, "objects",
          "verify checks every pair of blocks of two objects, and this scene has more than " +
              std::to_string(kMaxVerifiedPairs) +
              " (the limit); verify fewer objects, or run the scene with `recode run`, which "
              "tests only the pairs whose boxes overlap");
  }
  // Each block's world mesh once, shared by its pairs.
  std::vector<std::vector<std::shared_ptr<const core::TriangleMesh>>> meshes(trees.size());
  for (std::size_t i = 0; i < trees.size(); ++i)
    for (const int leaf : trees[i].leaves())
      meshes[i].push_back(std::make_shared<const core::TriangleMesh>(trees[i].worldMesh(leaf)));
  for (std::size_t i = 0; i < trees.size(); ++i)
    for (std::size_t j = i + 1; j < trees.size(); ++j)
      for (std::size_t la = 0; la < trees[i].leaves().size(); ++la)
        for (std::size_t lb = 0; lb < trees[j].leaves().size(); ++lb) {
          const auto leafA = static_cast<std::size_t>(trees[i].leaves()[la]);
          const auto leafB = static_cast<std::size_t>(trees[j].leaves()[lb]);
          PairToVerify p;
          p.label = trees[i].nodes()[leafA].path + " / " + trees[j].nodes()[leafB].path;
          p.a = meshes[i][la];
          p.b = meshes[j][lb];
          core::Aabb bounds = core::boundingBox(*p.a);
          bounds.extend(core::boundingBox(*p.b));
          p.frame = explain::resolveFrameNamed(scene, bounds, overrides);
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
    out.pairs.push_back({std::move(s.label),
                         std::make_shared<const core::TriangleMesh>(std::move(s.a)),
                         std::make_shared<const core::TriangleMesh>(std::move(s.b)), s.frame});
  return out;
}

}  // namespace recode::app
