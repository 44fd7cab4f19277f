#include "verify/pair_scenes.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "output/atomic_file.hpp"
#include "recode/io/double_text.hpp"
#include "recode/pair/view.hpp"

namespace recode::app {

namespace {

std::string offText(const core::TriangleMesh& mesh) {
  std::string text = "OFF\n" + std::to_string(mesh.vertexCount()) + " " +
                     std::to_string(mesh.triangleCount()) + " 0\n";
  for (const Eigen::Vector3d& v : mesh.vertices)
    text += io::shortestText(v.x()) + " " + io::shortestText(v.y()) + " " +
            io::shortestText(v.z()) + "\n";
  for (const core::Triangle& t : mesh.triangles)
    text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
            "\n";
  return text;
}

}  // namespace

std::size_t savePairScenes(const VerifyPairs& pairs, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::size_t written = 0;
  for (const PairToVerify& pair : pairs.pairs) {
    char stem[32];
    std::snprintf(stem, sizeof stem, "pair-%03zu", written);
    const std::string name(stem);
    output::writeFileAtomically(dir / (name + "-a.off"), offText(*pair.a));
    output::writeFileAtomically(dir / (name + "-b.off"), offText(*pair.b));
    const core::ViewWindow& w = pair.frame.window;
    nlohmann::ordered_json scene;
    scene["view"] = {{"axis", core::toString(pair.frame.axis)},
                     {"window", {w.umin, w.vmin, w.umax, w.vmax}},
                     {"resolution", {pair.frame.width, pair.frame.height}}};
    const auto label = [&](const char* block) { return pair.label + " " + block; };
    scene["objects"] = {{{"name", label("A")}, {"mesh", name + "-a.off"}},
                        {{"name", label("B")}, {"mesh", name + "-b.off"}}};
    output::writeFileAtomically(dir / (name + ".json"), scene.dump(2) + "\n");
    ++written;
  }
  return written;
}

}  // namespace recode::app
