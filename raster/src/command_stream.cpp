#include "recode/raster/command_stream.hpp"

#include <type_traits>

namespace recode::raster {

void replay(const std::vector<Command>& commands, DepthStencilDevice& device) {
  for (const Command& command : commands) {
    std::visit(
        [&device](const auto& c) {
          using T = std::decay_t<decltype(c)>;
          if constexpr (std::is_same_v<T, cmd::Scissor>) {
            device.setScissor(c.rect);
          } else if constexpr (std::is_same_v<T, cmd::ClearDepth>) {
            device.clearDepth(c.value);
          } else if constexpr (std::is_same_v<T, cmd::ClearStencil>) {
            device.clearStencil(c.value);
          } else if constexpr (std::is_same_v<T, cmd::DepthFunc>) {
            device.setDepthFunc(c.func);
          } else if constexpr (std::is_same_v<T, cmd::DepthWriteMask>) {
            device.setDepthWriteMask(c.write);
          } else if constexpr (std::is_same_v<T, cmd::StencilFunc>) {
            device.setStencilFunc(c.func, c.ref, c.valueMask);
          } else if constexpr (std::is_same_v<T, cmd::StencilOpsCmd>) {
            device.setStencilOps(c.face, c.ops);
          } else if constexpr (std::is_same_v<T, cmd::StencilWriteMask>) {
            device.setStencilWriteMask(c.mask);
          } else if constexpr (std::is_same_v<T, cmd::Cull>) {
            device.setCullMode(c.mode);
          } else {
            static_assert(std::is_same_v<T, cmd::Draw>);
            device.drawTriangles(c.vertices, c.indices);
          }
        },
        command);
  }
}

bool changesBuffers(const Command& command) {
  return std::holds_alternative<cmd::Draw>(command) ||
         std::holds_alternative<cmd::ClearDepth>(command) ||
         std::holds_alternative<cmd::ClearStencil>(command);
}

bool applyToState(const Command& command, RenderState& state, int width, int height) {
  return std::visit(
      [&](const auto& c) {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, cmd::Scissor>) {
          state.setScissor(c.rect, width, height);
        } else if constexpr (std::is_same_v<T, cmd::DepthFunc>) {
          state.depthFunc = c.func;
        } else if constexpr (std::is_same_v<T, cmd::DepthWriteMask>) {
          state.depthWrite = c.write;
        } else if constexpr (std::is_same_v<T, cmd::StencilFunc>) {
          state.stencilFunc = c.func;
          state.stencilRef = c.ref;
          state.stencilValueMask = c.valueMask;
        } else if constexpr (std::is_same_v<T, cmd::StencilOpsCmd>) {
          state.setStencilOps(c.face, c.ops);
        } else if constexpr (std::is_same_v<T, cmd::StencilWriteMask>) {
          state.stencilWriteMask = c.mask;
        } else if constexpr (std::is_same_v<T, cmd::Cull>) {
          state.cull = c.mode;
        } else {
          static_assert(std::is_same_v<T, cmd::ClearDepth> ||
                        std::is_same_v<T, cmd::ClearStencil> || std::is_same_v<T, cmd::Draw>);
          return false;  // changes the buffers, not the state
        }
        return true;
      },
      command);
}

RecordingDevice::RecordingDevice(DepthStencilDevice& inner) : ForwardingDevice(inner) {
  stream_.width = inner.width();
  stream_.height = inner.height();
}

void RecordingDevice::setScissor(const PixelRect& rect) {
  ForwardingDevice::setScissor(rect);
  stream_.commands.emplace_back(cmd::Scissor{rect});
}
void RecordingDevice::clearDepth(double depth) {
  ForwardingDevice::clearDepth(depth);
  stream_.commands.emplace_back(cmd::ClearDepth{depth});
}
void RecordingDevice::clearStencil(std::uint8_t value) {
  ForwardingDevice::clearStencil(value);
  stream_.commands.emplace_back(cmd::ClearStencil{value});
}
void RecordingDevice::setDepthFunc(CompareFunc func) {
  ForwardingDevice::setDepthFunc(func);
  stream_.commands.emplace_back(cmd::DepthFunc{func});
}
void RecordingDevice::setDepthWriteMask(bool write) {
  ForwardingDevice::setDepthWriteMask(write);
  stream_.commands.emplace_back(cmd::DepthWriteMask{write});
}
void RecordingDevice::setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) {
  ForwardingDevice::setStencilFunc(func, ref, valueMask);
  stream_.commands.emplace_back(cmd::StencilFunc{func, ref, valueMask});
}
void RecordingDevice::setStencilOps(Face face, const StencilOps& ops) {
  ForwardingDevice::setStencilOps(face, ops);
  stream_.commands.emplace_back(cmd::StencilOpsCmd{face, ops});
}
void RecordingDevice::setStencilWriteMask(std::uint8_t mask) {
  ForwardingDevice::setStencilWriteMask(mask);
  stream_.commands.emplace_back(cmd::StencilWriteMask{mask});
}
void RecordingDevice::setCullMode(CullMode mode) {
  ForwardingDevice::setCullMode(mode);
  stream_.commands.emplace_back(cmd::Cull{mode});
}
void RecordingDevice::drawTriangles(std::span<const WindowVertex> vertices,
                                    std::span<const std::uint32_t> indices) {
  ForwardingDevice::drawTriangles(vertices, indices);  // validates first
  stream_.commands.emplace_back(
      cmd::Draw{{vertices.begin(), vertices.end()}, {indices.begin(), indices.end()}});
}

}  // namespace recode::raster
