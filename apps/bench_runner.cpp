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
                                                    const std::vector<core::ObjectTree>& trees,
                                                    int threads) {
  switch (spec.kind) {
    case AlgorithmSpec::Kind::Recode: {
      core::RunOptions options;
      options.mor = spec.mor;
      options.drawOnScreen = spec.onScreen;
      options.threads = threads;
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

void setTimes(BenchRow& row, const std::vector<double>& us) {
  const core::Moments m = core::moments(us);
  row.totalMs = m.total / 1000.0;
  row.meanMs = m.mean / 1000.0;
  row.sdMs = m.sd / 1000.0;
}

void addCounters(RecodeCounters& sum, const core::FrameReport& r) {
  sum.boxTests += r.boxTests;
  sum.pairTests += r.pairTests;
  sum.stencilPixelsRead += r.stencilPixelsRead;
  sum.depthPixelsRead += r.depthPixelsRead;
}

// What every detector of one case shares: the scene and its object trees, which each run poses
// frame by frame in turn.
struct LoadedCase {
  LoadedCase(const Experiment& e, const std::string& name, int perBlock)
      : experiment(e),
        sceneName(name),
        trianglesPerBlock(perBlock),
        scene(core::builtinExperimentScene(name, perBlock)) {
    trees.reserve(scene.objects.size());
    for (const core::SceneObject& o : scene.objects) {
      trees.emplace_back(o);
      triangles += static_cast<long long>(trees.back().triangleCount());
    }
    frames = scene.frames.value_or(core::kDefaultRunFrames);
  }

  BenchRow row(const std::string& algorithm) const {
    BenchRow r;
    r.experiment = experiment.name;
    r.scene = sceneName;
    r.trianglesPerBlock = trianglesPerBlock;
    r.triangles = triangles;
    r.algorithm = algorithm;
    return r;
  }

  const Experiment& experiment;
  std::string sceneName;
  int trianglesPerBlock;
  core::Scene scene;
  std::vector<core::ObjectTree> trees;
  long long triangles = 0;
  int frames = 0;
};

// Counts detections (one a frame, the judge's and every algorithm's) and reports the share done.
class CaseSteps {
 public:
  CaseSteps(const CaseProgress& progress, double work) : progress_(progress), work_(work) {}
  void operator()() {
    done_ += 1.0;
    if (progress_)
      progress_(done_ / work_);
  }

 private:
  const CaseProgress& progress_;
  double work_;
  double done_ = 0.0;
};

// The judge's answers on the frames it judged: the truth the algorithms are scored against.
struct GroundTruth {
  explicit GroundTruth(int frames)
      : pairs(static_cast<std::size_t>(frames)), judged(static_cast<std::size_t>(frames), false) {}
  std::vector<std::vector<verify::LeafPairId>> pairs;  // by frame; empty where not judged
  std::vector<bool> judged;
};

BenchRow runJudge(LoadedCase& c, const std::vector<int>& judged, GroundTruth& truth,
                  CaseSteps& step) {
  const std::unique_ptr<verify::SceneDetector> judge = verify::makeExactDetector(c.trees);
  BenchRow row = c.row(judge->name());
  std::vector<double> us;
  for (int k : judged) {
    pose(c.trees, k);
    verify::Detection d = judge->detect(c.trees, k);
    us.push_back(d.collisionUs);
    row.contacts += static_cast<long long>(d.pairs.size());
    row.score += verify::scoreDetection(d.pairs, d.pairs);
    truth.pairs[static_cast<std::size_t>(k)] = std::move(d.pairs);
    truth.judged[static_cast<std::size_t>(k)] = true;
    step();
  }
  row.frames = static_cast<int>(judged.size());
  row.judgedFrames = row.frames;
  setTimes(row, us);
  return row;
}

BenchRow runAlgorithm(LoadedCase& c, const AlgorithmSpec& spec, int threads,
                      const GroundTruth& truth, CaseSteps& step) {
  const std::unique_ptr<verify::SceneDetector> detector =
      makeDetector(spec, c.scene, c.trees, threads);
  auto* recode = dynamic_cast<verify::RecodeDetector*>(detector.get());
  BenchRow row = c.row(spec.name);
  if (recode)
    row.recode = RecodeCounters{};
  pose(c.trees, 0);
  (void)detector->detect(c.trees, 0);  // warm-up, untimed
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(c.frames));
  for (int k = 0; k < c.frames; ++k) {
    pose(c.trees, k);
    const verify::Detection d = detector->detect(c.trees, k);
    us.push_back(d.collisionUs);
    row.contacts += static_cast<long long>(d.pairs.size());
    if (truth.judged[static_cast<std::size_t>(k)]) {
      row.score += verify::scoreDetection(truth.pairs[static_cast<std::size_t>(k)], d.pairs);
      ++row.judgedFrames;
    }
    if (recode)
      addCounters(*row.recode, recode->lastReport());
    step();
  }
  row.frames = c.frames;
  setTimes(row, us);
  return row;
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
                                   int trianglesPerBlock, int threads,
                                   const CaseProgress& progress) {
  LoadedCase c(experiment, sceneName, trianglesPerBlock);
  const std::vector<int> judged = judgedFrames(c.triangles, c.frames);
  const double work =
      static_cast<double>(judged.size()) +
      static_cast<double>(c.frames) * static_cast<double>(experiment.algorithms.size());
  CaseSteps step(progress, work);
  GroundTruth truth(c.frames);
  std::vector<BenchRow> rows;
  rows.push_back(runJudge(c, judged, truth, step));
  for (const AlgorithmSpec& spec : experiment.algorithms)
    rows.push_back(runAlgorithm(c, spec, threads, truth, step));
  return rows;
}

}  // namespace recode::app
