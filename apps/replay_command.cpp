#include "replay_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "pgm.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"

namespace recode::app {

namespace {

struct ReplayOptions {
  std::string file;
  std::string dumpStencil;
  std::string dumpDepth;
  bool json = false;
};

int runReplay(const ReplayOptions& o) {
  const raster::CommandFile file = raster::readCommandFile(o.file);
  const bool golden = file.hasExpected;
  const raster::GoldenVector& g = file.content;
  raster::CpuDevice dev(g.stream.width, g.stream.height);
  raster::replay(g.stream.commands, dev);

  const auto depth = dev.depthBuffer();
  const auto stencil = dev.stencilBuffer();
  long long depthDiff = 0, stencilDiff = 0;
  if (golden) {
    for (std::size_t i = 0; i < stencil.size(); ++i) {
      depthDiff += depth[i] != g.depth[i];
      stencilDiff += stencil[i] != g.stencil[i];
    }
  }
  const auto& c = dev.counters();
  if (!o.dumpStencil.empty()) {
    writePgmBottomUp(o.dumpStencil, dev.width(), dev.height(), {stencil.begin(), stencil.end()});
  }
  if (!o.dumpDepth.empty()) {
    std::vector<std::uint8_t> top8(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i)
      top8[i] = static_cast<std::uint8_t>(depth[i] >> 16);
    writePgmBottomUp(o.dumpDepth, dev.width(), dev.height(), top8);
  }
  if (o.json) {
    nlohmann::json j = {{"file", o.file},
                        {"width", dev.width()},
                        {"height", dev.height()},
                        {"commands", g.stream.commands.size()},
                        {"triangles", c.trianglesSubmitted},
                        {"degenerate", c.trianglesDegenerate},
                        {"culled", c.trianglesCulled},
                        {"fragments", c.fragments}};
    if (golden)
      j["mismatch"] = {{"depth", depthDiff}, {"stencil", stencilDiff}};
    std::cout << j.dump(1) << '\n';
  } else {
    std::cout << o.file << ": " << dev.width() << "x" << dev.height() << ", "
              << g.stream.commands.size() << " commands, " << c.trianglesSubmitted << " triangles ("
              << c.trianglesDegenerate << " zero-area, " << c.trianglesCulled << " culled), "
              << c.fragments << " fragments\n";
    if (golden) {
      std::cout << "expected buffers: " << (depthDiff + stencilDiff == 0 ? "match" : "MISMATCH")
                << " (" << depthDiff << " depth, " << stencilDiff << " stencil pixels differ)\n";
    }
  }
  return depthDiff + stencilDiff == 0 ? 0 : 1;
}

}  // namespace

void addReplayCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<ReplayOptions>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "Run a command stream or golden vector (JSON, docs/rasterization.md section 8) on "
      "the CPU device; for a golden vector, compare with its expected buffers (exit 1 "
      "on any difference)");
  cmd->add_option("FILE", opts->file, "recode-golden-1 or recode-commands-1 JSON file")->required();
  cmd->add_option("--dump-stencil", opts->dumpStencil, "write the stencil buffer as binary PGM");
  cmd->add_option("--dump-depth", opts->dumpDepth,
                  "write the top 8 bits of the depth buffer as binary PGM");
  cmd->add_flag("--json", opts->json, "print one JSON object");
  cmd->callback([opts, &exitCode]() { exitCode = runReplay(*opts); });
}

}  // namespace recode::app
