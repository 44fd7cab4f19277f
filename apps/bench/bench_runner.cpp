// Running one bench case: the judge, then each algorithm over the same motion.
#include "bench/bench_runner.hpp"

#include "bench/bench_closed.hpp"

#include <algorithm>
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
      options.pairMode = spec.mode;
      options.viewAxisRule = spec.viewAxisRule;
      options.batch = spec.batch;
      options.contactSchedule = spec.contactSchedule;
      options.batchDevicesPerSize = spec.batchDevicesPerSize;
      options.deviceSummaries = spec.deviceSummaries;
      options.keepContactPoints = false;  // the bench reports pairs and counters only
      return std::make_unique<verify::RecodeDetector>(scene, options, spec.device, spec.name);
    }
    case AlgorithmSpec::Kind::FclGjk:
      return verify::makeFclGjkDetector(trees);
    case AlgorithmSpec::Kind::FclObbrss:
      return verify::makeFclObbrssDetector(trees);
    case AlgorithmSpec::Kind::Bullet:
      return verify::makeBulletDetector(trees);
    case AlgorithmSpec::Kind::RecodeLayered:
    case AlgorithmSpec::Kind::BulletGImpact:
      break;  // pairs of closed meshes only (bench_closed.cpp)
  }
  throw std::invalid_argument("a scene of convex blocks cannot run " + spec.name);
}

void pose(std::vector<core::ObjectTree>& trees, int frame) {
  for (core::ObjectTree& t : trees)
    t.setFrame(frame);
}

void addCounters(RecodeCounters& sum, const core::FrameReport& r) {
  sum.boxTests += r.boxTests;
  sum.pairTests += r.pairTests;
  sum.stencilPixelsRead += r.stencilPixelsRead;
  sum.depthPixelsRead += r.depthPixelsRead;
  sum.submissions += r.submissions;
  sum.readbackBytes += r.readbackBytes;
  sum.deviceWaitUs += r.deviceWaitUs;
  sum.dispatches += r.dispatches;
  for (std::size_t k = 0; k < sum.stageUs.size(); ++k)
    sum.stageUs[k] += r.stageUs[k];
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
  setRowTimes(row, us);
  return row;
}

// recode-cpu's answers on the judged frames, kept so that recode-adaptive can count the pairs
// it found that recode-cpu missed.
using FoundByFrame = std::vector<std::vector<verify::LeafPairId>>;

long long missedButFound(const std::vector<verify::LeafPairId>& truth,
                         const std::vector<verify::LeafPairId>& reference,
                         const std::vector<verify::LeafPairId>& found) {
  long long n = 0;
  for (const verify::LeafPairId& p : truth)
    if (!std::binary_search(reference.begin(), reference.end(), p) &&
        std::binary_search(found.begin(), found.end(), p))
      ++n;
  return n;
}

BenchRow runAlgorithm(LoadedCase& c, const AlgorithmSpec& spec, int threads,
                      const GroundTruth& truth, CaseSteps& step, FoundByFrame& referenceFound) {
  const bool isReference = spec.name == "recode-cpu";
  const bool isAdaptive = spec.mode == core::PairMode::Adaptive && !referenceFound.empty();
  if (isReference)
    referenceFound.assign(truth.pairs.size(), {});
  const std::unique_ptr<verify::SceneDetector> detector =
      makeDetector(spec, c.scene, c.trees, threads);
  auto* recode = dynamic_cast<verify::RecodeDetector*>(detector.get());
  BenchRow row = c.row(spec.name);
  if (recode)
    row.recode = RecodeCounters{};
  if (isAdaptive)
    row.seenFiner = 0;
  pose(c.trees, 0);
  (void)detector->detect(c.trees, 0);  // warm-up, untimed
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(c.frames));
  for (int k = 0; k < c.frames; ++k) {
    pose(c.trees, k);
    verify::Detection d = detector->detect(c.trees, k);
    us.push_back(d.collisionUs);
    row.contacts += static_cast<long long>(d.pairs.size());
    const auto frame = static_cast<std::size_t>(k);
    if (truth.judged[frame]) {
      row.score += verify::scoreDetection(truth.pairs[frame], d.pairs);
      ++row.judgedFrames;
      if (isAdaptive)
        *row.seenFiner += missedButFound(truth.pairs[frame], referenceFound[frame], d.pairs);
      if (isReference)
        referenceFound[frame] = std::move(d.pairs);
    }
    if (recode)
      addCounters(*row.recode, recode->lastReport());
    step();
  }
  row.frames = c.frames;
  setRowTimes(row, us);
  return row;
}

}  // namespace

void setRowTimes(BenchRow& row, const std::vector<double>& us) {
  const core::Moments m = core::moments(us);
  row.totalMs = m.total / 1000.0;
  row.meanMs = m.mean / 1000.0;
  row.sdMs = m.sd / 1000.0;
}

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
  if (experiment.closedMeshes)
    return runClosedBenchCase(experiment, sceneName, trianglesPerBlock, progress);
  LoadedCase c(experiment, sceneName, trianglesPerBlock);
  const std::vector<int> judged = judgedFrames(c.triangles, c.frames);
  const double work =
      static_cast<double>(judged.size()) +
      static_cast<double>(c.frames) * static_cast<double>(experiment.algorithms.size());
  CaseSteps step(progress, work);
  GroundTruth truth(c.frames);
  std::vector<BenchRow> rows;
  rows.push_back(runJudge(c, judged, truth, step));
  FoundByFrame referenceFound;
  for (const AlgorithmSpec& spec : experiment.algorithms)
    rows.push_back(runAlgorithm(c, spec, threads, truth, step, referenceFound));
  return rows;
}

}  // namespace recode::app
