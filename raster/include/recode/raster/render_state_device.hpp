#pragma once
// The base of a device that keeps the state it is given in one RenderState, as the CPU
// reference does: the seven state setters of the interface are written here once, with the
// interface's checks (an unknown enumeration value throws before anything changes) and meaning
// (stencil ops for Front, Back or Both faces; the scissor clamped to the framebuffer). A device
// reads the state from state_ when it clears, draws or binds, and learns of each change through
// stateChanged, where a device over a graphics API passes it on.

#include <cstdint>

#include "recode/raster/device.hpp"
#include "recode/raster/state.hpp"

namespace recode::raster {

class RenderStateDevice : public DepthStencilDevice {
 public:
  void setScissor(const PixelRect& rect) final;
  void setDepthFunc(CompareFunc func) final;
  void setDepthWriteMask(bool write) final;
  void setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) final;
  void setStencilOps(Face face, const StencilOps& ops) final;
  void setStencilWriteMask(std::uint8_t mask) final;
  void setCullMode(CullMode mode) final;

  // The state the commands so far have set.
  [[nodiscard]] const RenderState& state() const { return state_; }
  [[nodiscard]] const PixelRect& scissor() const { return state_.scissor; }

 protected:
  // GL's default state for a width x height framebuffer (initialRenderState).
  RenderStateDevice(int width, int height);

  enum class StateChange {
    Scissor,
    DepthFunc,
    DepthWriteMask,
    StencilFunc,
    StencilOps,
    StencilWriteMask,
    CullMode
  };
  // Called after a setter has checked its arguments and stored them in state_; `face` is the
  // faces a StencilOps change was for (Both for the others). The default does nothing.
  virtual void stateChanged(StateChange change, Face face);

  RenderState state_;
};

}  // namespace recode::raster
