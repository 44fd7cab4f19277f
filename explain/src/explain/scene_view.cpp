#include "explain/scene_view.hpp"

#include <string>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/view.hpp"

namespace recode::explain {

namespace {

nlohmann::json blockJson(const std::string& name, const core::TriangleMesh& mesh) {
  nlohmann::json positions = nlohmann::json::array();
  for (const Eigen::Vector3d& p : mesh.vertices) {
    positions.push_back(p.x());
    positions.push_back(p.y());
    positions.push_back(p.z());
  }
  nlohmann::json triangles = nlohmann::json::array();
  for (const core::Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      triangles.push_back(t[k]);
  return {{"name", name}, {"positions", positions}, {"triangles", triangles}};
}

}  // namespace

nlohmann::json sceneViewJson(const PairSetup& setup, const core::PairResult& result) {
  const core::FrameSpec& f = setup.frame;
  const auto range =
      core::pairDepthRange(f.axis, core::boundingBox(setup.a), core::boundingBox(setup.b));
  const raster::PixelRect& m = result.mor;
  return {{"axis", std::string(core::toString(f.axis))},
          {"window", {f.window.umin, f.window.vmin, f.window.umax, f.window.vmax}},
          {"resolution", {f.width, f.height}},
          {"depth_range", {range[0], range[1]}},
          {"mor", m.empty() ? nlohmann::json(nullptr) : nlohmann::json{m.x0, m.y0, m.x1, m.y1}},
          {"blocks", {blockJson(setup.nameA, setup.a), blockJson(setup.nameB, setup.b)}}};
}

}  // namespace recode::explain
