#include "replay/replay_command.hpp"

#include <cstdint>
#include <iostream>
#include <nlohmann/json.hpp>
#include <span>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/pgm.hpp"
#include "recode/kit/buffer_diff.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"

namespace recode::app {

namespace {

struct ReplayOptions {
  std::string file;
  std::string dumpStencil;
  std::string dumpDepth;
  std::string dumpDepthRaw;
  bool diff = false;
  bool json = false;
};

// The whole depth buffer as little-endian uint32, bottom row first: the 24-bit values exactly,
// for tools that cannot read the golden JSON (width * height * 4 bytes, no header).
void writeDepthRaw(const std::string& path, std::span<const std::uint32_t> depth) {
  output::AtomicFile out(path, "--dump-depth-raw " + path);
  std::string bytes;
  bytes.reserve(depth.size() * 4);
  for (const std::uint32_t d : depth) {
    for (int shift = 0; shift < 32; shift += 8)
      bytes.push_back(static_cast<char>((d >> shift) & 0xFF));
  }
  out.write(bytes);
  out.commit();
}

nlohmann::json differencesToJson(const std::vector<kit::PixelDifference>& list) {
  nlohmann::json out = nlohmann::json::array();
  for (const kit::PixelDifference& d : list) {
    out.push_back({{"x", d.x},
                   {"y", d.y},
                   {"buffer", kit::toString(d.buffer)},
                   {"expected", d.expected},
                   {"got", d.got}});
  }
  return out;
}

int runReplay(const ReplayOptions& o) {
  const raster::CommandFile file = raster::readCommandFile(o.file);
  const bool golden = file.hasExpected;
  const raster::GoldenVector& g = file.content;
  if (o.diff && !golden)
    throw std::runtime_error("--diff needs a golden vector (recode-golden-1): " + o.file +
                             " is a command stream");
  raster::CpuDevice dev(g.stream.width, g.stream.height);
  raster::replay(g.stream.commands, dev);

  const auto depth = dev.depthBuffer();
  const auto stencil = dev.stencilBuffer();
  kit::BufferComparison cmp;
  if (golden)
    cmp = kit::compareBuffers(g, depth, stencil, o.diff ? SIZE_MAX : 0);
  const long long depthDiff = cmp.depthPixels, stencilDiff = cmp.stencilPixels;
  const auto& c = dev.counters();
  if (!o.dumpStencil.empty()) {
    output::writePgmBottomUp(o.dumpStencil, dev.width(), dev.height(),
                             {stencil.begin(), stencil.end()});
  }
  if (!o.dumpDepth.empty()) {
    std::vector<std::uint8_t> top8(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i)
      top8[i] = static_cast<std::uint8_t>(depth[i] >> 16);
    output::writePgmBottomUp(o.dumpDepth, dev.width(), dev.height(), top8);
  }
  if (!o.dumpDepthRaw.empty())
    writeDepthRaw(o.dumpDepthRaw, depth);
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
    if (o.diff)
      j["differences"] = differencesToJson(cmp.differences);
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
    for (const kit::PixelDifference& d : cmp.differences) {
      std::cout << "  (" << d.x << ", " << d.y << ") " << kit::toString(d.buffer) << " expected "
                << d.expected << ", got " << d.got << '\n';
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
  cmd->add_option("--dump-depth-raw", opts->dumpDepthRaw,
                  "write the depth buffer as little-endian uint32 per pixel, bottom row first "
                  "(width * height * 4 bytes)");
  cmd->add_flag("--diff", opts->diff,
                "for a golden vector: list every differing pixel (x, y, buffer, expected, got)");
  cmd->add_flag("--json", opts->json, "print one JSON object");
  cmd->callback([opts, &exitCode]() { exitCode = runReplay(*opts); });
}

}  // namespace recode::app
