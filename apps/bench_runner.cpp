// Running one bench case: the judge, then each algorithm over the same motion.
#include "bench_runner.hpp"

#include <memory>
#include <stdexcept>

#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/run_statistics.hpp"
#include "recode/sim/simulation.hpp"
#include "recode/verify/peer_detectors.hpp"

namespace recode::app {

namespace {

std::unique_ptr<verify::SceneDetector> makeDetector(const AlgorithmSpec& spec,
                                                    const core::Scene& scene,
                                                    const std::vector<core::ObjectTree>& trees) {
  switch (spec.kind) {
    case AlgorithmSpec::Kind::Recode: {
      core::RunOptions options;
      options.mor = spec.mor;
      options.drawOnScreen = spec.onScreen;
      return std::make_unique<verify::RecodeDetector>(scene, options, spec.device, spec.name);
    }
    case AlgorithmSpec::Kind::FclGjk:
      return verify::makeFclGjkDetector(trees);
    case AlgorithmSpec::Kind::FclObbrss:
      return verify::makeFclObbrssDetector(trees);
    case AlgorithmSpec::Kind::Bullet:
      return verify::makeBulletDetector(trees);
  }
  throw std::logic_error("unknown algorithm kind");
}

void pose(std::vector<core::ObjectTree>& trees, int frame) {
  for (core::ObjectTree& t : trees)
    t.setFrame(frame);
}

BenchRow rowFor(const Experiment& experiment, const std::string& scene, int trianglesPerBlock,
                long long triangles, const std::string& algorithm) {
  BenchRow row;
  row.experiment = experiment.name;
  row.scene = scene;
  row.trianglesPerBlock = trianglesPerBlock;
  row.triangles = triangles;
  row.algorithm = algorithm;
  return row;
}

void setTimes(BenchRow& row, const std::vector<double>& us) {
  const core::Moments m = core::moments(us);
  row.totalMs = m.total / 1000.0;
  row.meanMs = m.mean / 1000.0;
  row.sdMs = m.sd / 1000.0;
}

}  // namespace

std::vector<int> judgedFrames(long long triangles, int frames) {
  std::vector<int> judged;
  const int step = triangles <= kJudgeEveryFrameUpTo ? 1 : kJudgeSampleStep;
  for (int k = 0; k < frames; k += step)
    judged.push_back(k);
  return judged;
}

std::vector<BenchRow> runBenchCase(const Experiment& experiment, const std::string& sceneName,
                                   int trianglesPerBlock, const CaseProgress& progress) {
  const core::Scene scene = core::builtinExperimentScene(sceneName, trianglesPerBlock);
  std::vector<core::ObjectTree> trees;
  trees.reserve(scene.objects.size());
  long long triangles = 0;
  for (const core::SceneObject& o : scene.objects) {
    trees.emplace_back(o);
    triangles += static_cast<long long>(trees.back().triangleCount());
  }
  const int frames = scene.frames.value_or(core::kDefaultRunFrames);
  const std::vector<int> judged = judgedFrames(triangles, frames);
  const double work =
      static_cast<double>(judged.size()) +
      static_cast<double>(frames) * static_cast<double>(experiment.algorithms.size());
  double done = 0.0;
  const auto step = [&]() {
    done += 1.0;
    if (progress)
      progress(done / work);
  };

  // The judge: its answers on the judged frames are the ground truth.
  std::vector<BenchRow> rows;
  std::vector<std::vector<verify::LeafPairId>> truth(static_cast<std::size_t>(frames));
  std::vector<bool> isJudged(static_cast<std::size_t>(frames), false);
  {
    const std::unique_ptr<verify::SceneDetector> judge = verify::makeExactDetector(trees);
    BenchRow row = rowFor(experiment, sceneName, trianglesPerBlock, triangles, judge->name());
    std::vector<double> us;
    for (int k : judged) {
      pose(trees, k);
      verify::Detection d = judge->detect(trees, k);
      us.push_back(d.collisionUs);
      row.contacts += static_cast<long long>(d.pairs.size());
      row.score += verify::scoreDetection(d.pairs, d.pairs);
      truth[static_cast<std::size_t>(k)] = std::move(d.pairs);
      isJudged[static_cast<std::size_t>(k)] = true;
      step();
    }
    row.frames = static_cast<int>(judged.size());
    row.judgedFrames = row.frames;
    setTimes(row, us);
    rows.push_back(std::move(row));
  }

  for (const AlgorithmSpec& spec : experiment.algorithms) {
    const std::unique_ptr<verify::SceneDetector> detector = makeDetector(spec, scene, trees);
    auto* recode = dynamic_cast<verify::RecodeDetector*>(detector.get());
    BenchRow row = rowFor(experiment, sceneName, trianglesPerBlock, triangles, spec.name);
    if (recode)
      row.recode = RecodeCounters{};
    pose(trees, 0);
    (void)detector->detect(trees, 0);  // warm-up, untimed
    std::vector<double> us;
    us.reserve(static_cast<std::size_t>(frames));
    for (int k = 0; k < frames; ++k) {
      pose(trees, k);
      const verify::Detection d = detector->detect(trees, k);
      us.push_back(d.collisionUs);
      row.contacts += static_cast<long long>(d.pairs.size());
      if (isJudged[static_cast<std::size_t>(k)]) {
        row.score += verify::scoreDetection(truth[static_cast<std::size_t>(k)], d.pairs);
        ++row.judgedFrames;
      }
      if (recode) {
        const core::FrameReport& r = recode->lastReport();
        row.recode->boxTests += r.boxTests;
        row.recode->pairTests += r.pairTests;
        row.recode->stencilPixelsRead += r.stencilPixelsRead;
        row.recode->depthPixelsRead += r.depthPixelsRead;
      }
      step();
    }
    row.frames = frames;
    setTimes(row, us);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace recode::app
