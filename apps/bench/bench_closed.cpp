// Running one case of the closed-mesh experiment: the judge, then each algorithm on the same
// poses (bench_closed.hpp).
#include "bench/bench_closed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "recode/geometry/generators.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/closed_peers.hpp"
#include "recode/verify/layer_oracle.hpp"

namespace recode::app {

namespace {

// Poses along each path; the judge samples every kJudgeSampleStep-th above
// kJudgeEveryFrameUpTo triangles, as on the other experiments.
constexpr int kPoses = 41;

// A fixed mesh A at the origin and a moving mesh B, with B's pose at each of kPoses steps.
struct ClosedPairPath {
  std::string name;
  // The meshes for a tessellation parameter n (rings of a torus or a sphere): about 4 n^2
  // triangles each.
  std::function<core::TriangleMesh(int n)> makeA;
  std::function<core::TriangleMesh(int n)> makeB;
  std::function<Eigen::Isometry3d(double t)> poseB;  // t in [0, 1] along the path
};

// A torus (radius 1, tube 0.4, about the z axis) and a ball of radius 0.25 moving along the x
// axis from x = -2 to 2: it crosses the tube's surface, lies wholly inside the tube around
// x = -1 and x = 1 (a containment, which a test of surfaces alone reports as apart), and passes
// through the hole apart from the torus around x = 0.
ClosedPairPath ballThroughTorus() {
  return {"ball-through-torus", [](int n) { return core::makeTorus(1.0, 0.4, 2 * n, n); },
          [](int n) { return core::makeSphere(0.25, 2 * n, n + 1); },
          [](double t) {
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.translation() = Eigen::Vector3d(-2.0 + 4.0 * t, 0.0, 0.0);
            return pose;
          }};
}

// Two linked rings (radius 1, tube 0.25): B stands in the x-z plane through A's hole, turns
// about its own vertical axis and slides along x, so that the tubes pass apart, touch and cross;
// their convex hulls overlap at every pose.
ClosedPairPath linkedRings() {
  const auto ring = [](int n) { return core::makeTorus(1.0, 0.25, 2 * n, n); };
  return {"linked-rings", ring, ring, [](double t) {
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.translate(Eigen::Vector3d(1.0 + 0.8 * t, 0.0, 0.0));
            pose.rotate(Eigen::AngleAxisd(0.5 * std::numbers::pi * t, Eigen::Vector3d::UnitZ()));
            pose.rotate(Eigen::AngleAxisd(0.5 * std::numbers::pi, Eigen::Vector3d::UnitX()));
            return pose;
          }};
}

const std::vector<ClosedPairPath>& paths() {
  static const std::vector<ClosedPairPath> list{ballThroughTorus(), linkedRings()};
  return list;
}

const ClosedPairPath& pathNamed(const std::string& name) {
  for (const ClosedPairPath& p : paths())
    if (p.name == name)
      return p;
  throw std::invalid_argument("no closed-mesh path \"" + name + "\"");
}

// The tessellation parameter whose meshes have about `triangles` triangles each (4 n^2).
int ringsFor(int triangles) {
  return std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
}

double microsecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
      .count();
}

// One pose's answer and what it cost.
struct PoseAnswer {
  bool collide = false;
  double us = 0.0;
};

// An algorithm of the case: answers a pose (an index into the path's poses).
class ClosedAlgorithm {
 public:
  virtual ~ClosedAlgorithm() = default;
  virtual PoseAnswer answer(int pose) = 0;
  virtual void resetCounters() {}  // after the warm-up
  virtual void addCounters(BenchRow&) {}
};

// What the algorithms of a case share: the meshes in their own coordinates and B's poses.
struct ClosedCase {
  ClosedCase(const ClosedPairPath& path, int trianglesPerMesh)
      : a(path.makeA(ringsFor(trianglesPerMesh))), b(path.makeB(ringsFor(trianglesPerMesh))) {
    for (int k = 0; k < kPoses; ++k)
      posesB.push_back(path.poseB(static_cast<double>(k) / (kPoses - 1)));
  }
  core::TriangleMesh a;  // fixed, at the identity
  core::TriangleMesh b;
  std::vector<Eigen::Isometry3d> posesB;
};

// The layered pair on the CPU device, at `width` x `width` pixels around both meshes' box, the
// view along z. Its time per pose: placing B, the frame, the passes and the sweep (A's box is
// computed once: A does not move).
class LayeredAlgorithm final : public ClosedAlgorithm {
 public:
  LayeredAlgorithm(const ClosedCase& c, int width)
      : case_(c), width_(width), device_(width, width), boundsA_(core::boundingBox(c.a)) {}

  PoseAnswer answer(int pose) override {
    const auto start = std::chrono::steady_clock::now();
    core::transformInto(case_.b, case_.posesB[static_cast<std::size_t>(pose)], placedB_);
    core::Aabb bounds = boundsA_;  // A does not move
    bounds.extend(core::boundingBox(placedB_));
    core::PairRequest request;
    request.frame.axis = core::ViewAxis::Z;
    request.frame.width = request.frame.height = width_;
    request.frame.window =
        core::defaultWindow(core::ViewAxis::Z, bounds, std::array<int, 2>{width_, width_});
    request.contact = false;
    request.keepPixels = false;
    const core::LayeredPairResult r = core::collideLayered(device_, case_.a, placedB_, request);
    const double us = microsecondsSince(start);
    counters_.boxTests += 1;
    counters_.pairTests += r.boxesOverlap ? 1 : 0;
    counters_.stencilPixelsRead += r.stencilPixelsRead;
    counters_.depthPixelsRead += r.depthPixelsRead;
    layered_.passes += r.passes;
    layered_.layersA = std::max(layered_.layersA, r.layersA);
    layered_.layersB = std::max(layered_.layersB, r.layersB);
    return {r.collide, us};
  }

  void resetCounters() override {
    counters_ = {};
    layered_ = {};
  }

  void addCounters(BenchRow& row) override {
    row.recode = counters_;
    row.layered = layered_;
  }

 private:
  const ClosedCase& case_;
  int width_;
  raster::CpuDevice device_;
  core::Aabb boundsA_;
  core::TriangleMesh placedB_;
  RecodeCounters counters_;
  LayeredCounters layered_;
};

// A peer (closed_peers.hpp): its time per pose is the query with both poses.
class PeerAlgorithm final : public ClosedAlgorithm {
 public:
  PeerAlgorithm(const ClosedCase& c, std::unique_ptr<verify::ClosedPairPeer> peer)
      : case_(c), peer_(std::move(peer)) {}

  PoseAnswer answer(int pose) override {
    const auto start = std::chrono::steady_clock::now();
    const bool collide =
        peer_->collide(Eigen::Isometry3d::Identity(), case_.posesB[static_cast<std::size_t>(pose)]);
    return {collide, microsecondsSince(start)};
  }

 private:
  const ClosedCase& case_;
  std::unique_ptr<verify::ClosedPairPeer> peer_;
};

std::unique_ptr<ClosedAlgorithm> makeAlgorithm(const AlgorithmSpec& spec, const ClosedCase& c) {
  switch (spec.kind) {
    case AlgorithmSpec::Kind::RecodeLayered:
      return std::make_unique<LayeredAlgorithm>(c, spec.resolution);
    case AlgorithmSpec::Kind::FclObbrss:
      return std::make_unique<PeerAlgorithm>(
          c, verify::makeFclObbrssClosedPeer(c.a, c.b, spec.allContacts));
    case AlgorithmSpec::Kind::BulletGImpact:
      return std::make_unique<PeerAlgorithm>(c, verify::makeBulletGImpactClosedPeer(c.a, c.b));
    case AlgorithmSpec::Kind::Recode:
    case AlgorithmSpec::Kind::FclGjk:
    case AlgorithmSpec::Kind::Bullet:
      break;  // scenes of convex blocks only (bench_runner.cpp)
  }
  throw std::invalid_argument("the closed-mesh experiment cannot run " + spec.name);
}

// CGAL's exact verdict on the placed meshes; a build without CGAL has no judge (and
// requireEverything refuses the bench before any case runs).
bool judgeMeet(const core::TriangleMesh& a, const core::TriangleMesh& b) {
#if RECODE_HAVE_CGAL
  return verify::closedMeshesMeet(a, b);
#else
  (void)a;
  (void)b;
  throw std::runtime_error(
      "recode bench closed needs the CGAL judge (RECODE_WITH_CGAL; libcgal-dev)");
#endif
}

// The one pair of a case, as the scores count pairs.
const std::vector<verify::LeafPairId> kThePair{{0, 0, 1, 0}};
const std::vector<verify::LeafPairId> kNoPair{};

const std::vector<verify::LeafPairId>& pairsOf(bool collide) {
  return collide ? kThePair : kNoPair;
}

}  // namespace

const std::vector<std::string>& closedBenchScenes() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const ClosedPairPath& p : paths())
      list.push_back(p.name);
    return list;
  }();
  return names;
}

std::vector<BenchRow> runClosedBenchCase(const Experiment& experiment, const std::string& scene,
                                         int trianglesPerMesh, const CaseProgress& progress) {
  const ClosedCase c(pathNamed(scene), trianglesPerMesh);
  const long long triangles = static_cast<long long>(c.a.triangles.size() + c.b.triangles.size());
  const std::vector<int> judged = judgedFrames(triangles, kPoses);
  const double work = static_cast<double>(judged.size() + experiment.algorithms.size() * kPoses);
  double done = 0.0;
  const auto step = [&] {
    done += 1.0;
    if (progress)
      progress(done / work);
  };
  const auto row = [&](const std::string& algorithm) {
    BenchRow r;
    r.experiment = experiment.name;
    r.scene = scene;
    r.trianglesPerBlock = trianglesPerMesh;  // the level asked for; `triangles` is the count
    r.triangles = triangles;
    r.algorithm = algorithm;
    return r;
  };

  // The judge: CGAL on the placed meshes, exactly.
  std::vector<int> truth(kPoses, -1);  // 1 collide, 0 apart, -1 not judged
  BenchRow judgeRow = row("cgal");
  std::vector<double> judgeUs;
  for (int k : judged) {
    const auto start = std::chrono::steady_clock::now();
    const bool meet = judgeMeet(c.a, core::transformed(c.b, c.posesB[static_cast<std::size_t>(k)]));
    judgeUs.push_back(microsecondsSince(start));
    truth[static_cast<std::size_t>(k)] = meet ? 1 : 0;
    judgeRow.contacts += meet ? 1 : 0;
    judgeRow.score += verify::scoreDetection(pairsOf(meet), pairsOf(meet));
    step();
  }
  judgeRow.frames = judgeRow.judgedFrames = static_cast<int>(judged.size());
  setRowTimes(judgeRow, judgeUs);
  std::vector<BenchRow> rows{judgeRow};

  for (const AlgorithmSpec& spec : experiment.algorithms) {
    const std::unique_ptr<ClosedAlgorithm> algorithm = makeAlgorithm(spec, c);
    (void)algorithm->answer(0);  // warm-up, untimed
    algorithm->resetCounters();
    BenchRow r = row(spec.name);
    std::vector<double> us;
    for (int k = 0; k < kPoses; ++k) {
      const PoseAnswer a = algorithm->answer(k);
      us.push_back(a.us);
      r.contacts += a.collide ? 1 : 0;
      if (truth[static_cast<std::size_t>(k)] >= 0) {
        r.score += verify::scoreDetection(pairsOf(truth[static_cast<std::size_t>(k)] == 1),
                                          pairsOf(a.collide));
        ++r.judgedFrames;
      }
      step();
    }
    r.frames = kPoses;
    setRowTimes(r, us);
    algorithm->addCounters(r);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace recode::app
