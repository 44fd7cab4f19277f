#include "gpu_commands.hpp"

#include <cstring>
#include <nlohmann/json.hpp>
#include <type_traits>
#include <variant>

#include "recode/backends/exact_proxy.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/golden.hpp"

namespace recode::wasm {

namespace {

nlohmann::ordered_json opsJson(const raster::StencilOps& ops) {
  return {raster::toString(ops.stencilFail), raster::toString(ops.depthFail),
          raster::toString(ops.depthPass)};
}

// The names are the contract's (toString); the page maps them to WebGPU's.
nlohmann::ordered_json stateJson(const raster::RenderState& s) {
  nlohmann::ordered_json j;
  j["scissor"] = {s.scissor.x0, s.scissor.y0, s.scissor.x1, s.scissor.y1};
  j["depth_func"] = raster::toString(s.depthFunc);
  j["depth_write"] = s.depthWrite;
  j["stencil_func"] = raster::toString(s.stencilFunc);
  j["stencil_ref"] = s.stencilRef;
  j["stencil_value_mask"] = s.stencilValueMask;
  j["stencil_write_mask"] = s.stencilWriteMask;
  j["front_ops"] = opsJson(s.frontOps);
  j["back_ops"] = opsJson(s.backOps);
  return j;
}

// The records' 32-bit fields as unsigned words (the page reinterprets the signed ones).
std::vector<std::uint32_t> proxyWords(const std::vector<backends::ProxyTriangle>& proxies) {
  std::vector<std::uint32_t> words(proxies.size() * sizeof(backends::ProxyTriangle) / 4);
  if (!proxies.empty())
    std::memcpy(words.data(), proxies.data(), words.size() * 4);
  return words;
}

}  // namespace

std::string gpuCommands(const std::string& path) {
  raster::CommandFile file = raster::readCommandFile(path);
  raster::GoldenVector& g = file.content;
  if (!file.hasExpected) {
    // A bare command stream: its expected buffers are the reference's, the CPU device's.
    raster::CpuDevice device(g.stream.width, g.stream.height);
    raster::replay(g.stream.commands, device);
    const raster::PixelRect all{0, 0, g.stream.width, g.stream.height};
    g.depth = device.readDepth(all);
    g.stencil = device.readStencil(all);
  }
  const int width = g.stream.width, height = g.stream.height;
  raster::RenderState state = raster::initialRenderState(width, height);
  nlohmann::ordered_json commands = nlohmann::ordered_json::array();
  for (const raster::Command& command : g.stream.commands) {
    std::visit(
        [&](const auto& c) {
          using T = std::decay_t<decltype(c)>;
          if constexpr (std::is_same_v<T, raster::cmd::Draw>) {
            nlohmann::ordered_json j;
            j["draw"] = stateJson(state);
            j["proxies"] = proxyWords(backends::buildProxyTriangles(c.vertices, c.indices, state));
            commands.push_back(std::move(j));
          } else if constexpr (std::is_same_v<T, raster::cmd::ClearDepth>) {
            if (!state.depthWrite)
              return;  // GL's depth mask applies to clears, as in CpuDevice
            nlohmann::ordered_json j;
            j["clear_depth"] = stateJson(state);
            j["q"] = raster::quantizeDepth(c.value);
            commands.push_back(std::move(j));
          } else if constexpr (std::is_same_v<T, raster::cmd::ClearStencil>) {
            nlohmann::ordered_json j;
            j["clear_stencil"] = stateJson(state);
            j["value"] = c.value;
            commands.push_back(std::move(j));
          } else {
            raster::applyToState(command, state, width, height);
          }
        },
        command);
  }
  nlohmann::ordered_json j;
  j["width"] = width;
  j["height"] = height;
  j["commands"] = std::move(commands);
  j["depth"] = g.depth;
  j["stencil"] = g.stencil;
  return j.dump();
}

}  // namespace recode::wasm
