#pragma once
// The closed-mesh experiment of `recode bench` (docs/benchmarks.md, "Closed meshes against the
// peers"): two closed, non-convex meshes, one fixed and one moving along a path that crosses the
// other's surface and, in one of the paths, passes wholly inside it, at several triangle counts.
// CGAL judges each pose (verify::closedMeshesMeet: the surfaces meet or one mesh is inside the
// other); the layered pair at several resolutions and the surface-only peers (fcl-obbrss,
// bullet-gimpact) answer the same poses, timed pose by pose, and are scored against the judge.

#include <string>
#include <vector>

#include "bench/bench_runner.hpp"

namespace recode::app {

// The paths, by the names the experiment lists as its scenes.
[[nodiscard]] const std::vector<std::string>& closedBenchScenes();

// The case `scene` with meshes of about `trianglesPerMesh` triangles each: the judge's row, then
// one row per algorithm of the experiment (kinds RecodeLayered, FclObbrss, BulletGImpact).
// Throws std::invalid_argument for an unknown scene or an algorithm of another kind.
[[nodiscard]] std::vector<BenchRow> runClosedBenchCase(const Experiment& experiment,
                                                       const std::string& scene,
                                                       int trianglesPerMesh,
                                                       const CaseProgress& progress);

}  // namespace recode::app
