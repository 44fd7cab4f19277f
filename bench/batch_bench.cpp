// The C++ side of the Python batch benchmark (bench/python_batch_bench.py, docs/benchmarks.md):
// recode::collide on the two cones of examples/two_cones.cpp (pixel size 0.01) with the upper
// cone at 1,000 poses, one call per pose, as a C++ planning loop pays it. One iteration is the
// whole batch (its time in ms is the microseconds per pose); the Python script times
// recode.collide_poses on the same poses.
//
//   build/bench/recode_batch_bench --benchmark_min_time=3
#include <benchmark/benchmark.h>

#include <vector>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"

namespace {

using namespace recode;

constexpr int kPoses = 1000;

// Pose i of the batch: the upper cone upside down (a half turn about x), moved along x from
// -0.2 to 0.2 and up from 3.5 to 4.0 (its tip from 0.5 into the lower one's to 0.0).
std::vector<Eigen::Isometry3d> batchPoses() {
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < kPoses; ++i) {
    const double t = static_cast<double>(i) / (kPoses - 1);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
    pose.translation() = Eigen::Vector3d(-0.2 + 0.4 * t, 0.0, 3.5 + 0.5 * t);
    poses.push_back(pose);
  }
  return poses;
}

void conesAtPoses(benchmark::State& state) {
  const auto cone =
      CollisionGeometry::single(ConvexBlock::fromMesh(core::makeCone(1.0, 2.0, 32), "cone"));
  const CollisionObject lower(cone);
  CollisionObject upper(cone);
  CollisionRequest request;
  request.pixelSize = 0.01;
  const std::vector<Eigen::Isometry3d> poses = batchPoses();
  CollisionResult result;
  long long contacts = 0;
  // Warm, as the Python script is: this thread's devices for the frame sizes the poses need.
  for (const Eigen::Isometry3d& pose : poses) {
    upper.setTransform(pose);
    collide(lower, upper, request, result);
  }
  for (auto _ : state) {
    contacts = 0;
    for (const Eigen::Isometry3d& pose : poses) {
      upper.setTransform(pose);
      contacts += collide(lower, upper, request, result) ? 1 : 0;
    }
    benchmark::DoNotOptimize(contacts);
  }
  state.counters["poses"] = kPoses;
  state.counters["contacts"] = static_cast<double>(contacts);
}
BENCHMARK(conesAtPoses)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
