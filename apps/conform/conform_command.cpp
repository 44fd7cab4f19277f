#include "conform/conform_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/device_option.hpp"
#include "recode/backends/device_registry.hpp"
#include "recode/kit/buffer_diff.hpp"
#include "recode/raster/golden.hpp"

namespace recode::app {

namespace {

namespace fs = std::filesystem;

struct ConformOptions {
  std::string device = "cpu";
  std::string golden = RECODE_SOURCE_DATA_DIR "/golden";
  bool json = false;
};

struct VectorResult {
  std::string file;  // relative to the golden directory
  long long depthPixels = 0, stencilPixels = 0;
  std::optional<kit::PixelDifference> first;
  std::string deviceError;  // the device refused the stream (a failure, not an error)
  [[nodiscard]] bool passed() const {
    return deviceError.empty() && depthPixels == 0 && stencilPixels == 0;
  }
};

// Every *.json under `dir`, recursively, in a fixed order (by path).
std::vector<fs::path> goldenFiles(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw std::runtime_error("--golden " + dir.string() + ": not a directory");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw std::runtime_error("--golden " + dir.string() + ": no golden vectors (*.json)");
  return files;
}

// A malformed file is an error of the run (FormatError propagates); a device that throws on a
// valid stream fails the vector.
VectorResult conformVector(const fs::path& file, const fs::path& dir, backends::DeviceKind kind) {
  const raster::GoldenVector g = raster::readGolden(file);
  VectorResult r;
  r.file = fs::relative(file, dir).generic_string();
  auto device = backends::makeDevice(kind, g.stream.width, g.stream.height);
  try {
    raster::replay(g.stream.commands, *device);
  } catch (const std::invalid_argument& e) {
    r.deviceError = e.what();
    return r;
  }
  const raster::PixelRect all{0, 0, g.stream.width, g.stream.height};
  const auto depth = device->readDepth(all);
  const auto stencil = device->readStencil(all);
  const kit::BufferComparison cmp = kit::compareBuffers(g, depth, stencil, 1);
  r.depthPixels = cmp.depthPixels;
  r.stencilPixels = cmp.stencilPixels;
  r.first = cmp.first();
  return r;
}

nlohmann::json resultToJson(const VectorResult& r) {
  nlohmann::json j = {{"file", r.file},
                      {"passed", r.passed()},
                      {"depth_pixels", r.depthPixels},
                      {"stencil_pixels", r.stencilPixels},
                      {"first_difference", nullptr}};
  if (r.first) {
    j["first_difference"] = {{"x", r.first->x},
                             {"y", r.first->y},
                             {"buffer", kit::toString(r.first->buffer)},
                             {"expected", r.first->expected},
                             {"got", r.first->got}};
  }
  if (!r.deviceError.empty())
    j["error"] = r.deviceError;
  return j;
}

void printResult(std::ostream& out, const VectorResult& r) {
  out << (r.passed() ? "  pass  " : "  FAIL  ") << r.file;
  if (!r.deviceError.empty()) {
    out << ": the device refused the stream: " << r.deviceError;
  } else if (r.first) {
    out << ": " << r.depthPixels << " depth, " << r.stencilPixels
        << " stencil pixels differ; first at (" << r.first->x << ", " << r.first->y << ") "
        << kit::toString(r.first->buffer) << " expected " << r.first->expected << ", got "
        << r.first->got;
  }
  out << '\n';
}

int runConform(const ConformOptions& o) {
  const backends::DeviceKind kind = backends::parseDeviceKind(o.device);
  // A device this build cannot make is an error before any vector is read.
  (void)backends::makeDevice(kind, 1, 1);
  const fs::path dir = o.golden;
  std::vector<VectorResult> results;
  for (const fs::path& file : goldenFiles(dir))
    results.push_back(conformVector(file, dir, kind));
  const auto passed = std::count_if(results.begin(), results.end(),
                                    [](const VectorResult& r) { return r.passed(); });
  const auto failed = static_cast<std::ptrdiff_t>(results.size()) - passed;
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const VectorResult& r : results)
      list.push_back(resultToJson(r));
    const nlohmann::json j = {{"device", o.device},        {"golden", dir.string()},
                              {"vectors", results.size()}, {"passed", passed},
                              {"failed", failed},          {"results", list}};
    std::cout << j.dump(1) << '\n';
  } else {
    std::cout << "recode conform: device " << o.device << ", " << results.size()
              << " golden vectors under " << dir.string() << '\n';
    for (const VectorResult& r : results)
      printResult(std::cout, r);
    std::cout << results.size() << " vectors: " << passed << " passed, " << failed << " failed\n";
  }
  return failed == 0 ? 0 : 2;
}

}  // namespace

void addConformCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ConformOptions>();
  CLI::App* cmd = app.add_subcommand(
      "conform",
      "Replay every golden vector under a directory on a device and compare every depth and "
      "stencil value (exit 2 when any vector fails)");
  addDeviceOption(*cmd, o->device, "the device");
  cmd->add_option("--golden", o->golden, "directory searched recursively for *.json vectors")
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print one JSON object instead of the report");
  cmd->callback([o, &exitCode]() { exitCode = runConform(*o); });
}

}  // namespace recode::app
