#pragma once
// A device command stream as data: what the algorithm said to a device, so that it can be
// saved (golden vectors, bug reports), replayed on another device (OSMesa, a GPU back end),
// and compared. RecordingDevice captures a stream while forwarding it.

#include <cstdint>
#include <variant>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/raster/forwarding_device.hpp"

namespace recode::raster {

namespace cmd {
struct Scissor {
  PixelRect rect;
};
struct ClearDepth {
  double value = 1.0;
};
struct ClearStencil {
  std::uint8_t value = 0;
};
struct DepthFunc {
  CompareFunc func = CompareFunc::Less;
};
struct DepthWriteMask {
  bool write = true;
};
struct StencilFunc {
  CompareFunc func = CompareFunc::Always;
  std::uint8_t ref = 0;
  std::uint8_t valueMask = 0xFF;
};
struct StencilOpsCmd {
  Face face = Face::Both;
  StencilOps ops;
};
struct StencilWriteMask {
  std::uint8_t mask = 0xFF;
};
struct Cull {
  CullMode mode = CullMode::None;
};
struct Draw {
  std::vector<WindowVertex> vertices;
  std::vector<std::uint32_t> indices;
};
}  // namespace cmd

using Command = std::variant<cmd::Scissor, cmd::ClearDepth, cmd::ClearStencil, cmd::DepthFunc,
                             cmd::DepthWriteMask, cmd::StencilFunc, cmd::StencilOpsCmd,
                             cmd::StencilWriteMask, cmd::Cull, cmd::Draw>;

struct CommandStream {
  int width = 0;
  int height = 0;
  std::vector<Command> commands;
};

// Sends every command to `device`, in order. The device's size is not changed.
void replay(const std::vector<Command>& commands, DepthStencilDevice& device);

// Applies a state command to `state` as every device does (the scissor clamped to a width x
// height framebuffer). Returns false, changing nothing, for a command that changes the buffers
// (a clear or a draw): for tools that follow a stream's state without a device.
bool applyToState(const Command& command, RenderState& state, int width, int height);

// Whether the command can change the buffers (a clear or a draw): the commands after which
// parity checks read both devices back.
[[nodiscard]] bool changesBuffers(const Command& command);

// Forwards every call to an inner device and appends it to a stream once the inner device has
// taken it (a command it rejects is not recorded).
class RecordingDevice final : public ForwardingDevice {
 public:
  explicit RecordingDevice(DepthStencilDevice& inner);

  [[nodiscard]] const CommandStream& stream() const { return stream_; }

  void setScissor(const PixelRect& rect) override;
  void clearDepth(double depth) override;
  void clearStencil(std::uint8_t value) override;
  void setDepthFunc(CompareFunc func) override;
  void setDepthWriteMask(bool write) override;
  void setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) override;
  void setStencilOps(Face face, const StencilOps& ops) override;
  void setStencilWriteMask(std::uint8_t mask) override;
  void setCullMode(CullMode mode) override;
  void drawTriangles(std::span<const WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;

 private:
  CommandStream stream_;
};

}  // namespace recode::raster
