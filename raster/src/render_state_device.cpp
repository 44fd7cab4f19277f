#include "recode/raster/render_state_device.hpp"

#include "recode/raster/device_checks.hpp"

namespace recode::raster {

RenderStateDevice::RenderStateDevice(int width, int height)
    : state_(initialRenderState(width, height)) {}

void RenderStateDevice::stateChanged(StateChange /*change*/, Face /*face*/) {}

void RenderStateDevice::setScissor(const PixelRect& rect) {
  state_.setScissor(rect, width(), height());
  stateChanged(StateChange::Scissor, Face::Both);
}

void RenderStateDevice::setDepthFunc(CompareFunc func) {
  checkCompareFunc(func, "setDepthFunc");
  state_.depthFunc = func;
  stateChanged(StateChange::DepthFunc, Face::Both);
}

void RenderStateDevice::setDepthWriteMask(bool write) {
  state_.depthWrite = write;
  stateChanged(StateChange::DepthWriteMask, Face::Both);
}

void RenderStateDevice::setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) {
  checkCompareFunc(func, "setStencilFunc");
  state_.stencilFunc = func;
  state_.stencilRef = ref;
  state_.stencilValueMask = valueMask;
  stateChanged(StateChange::StencilFunc, Face::Both);
}

void RenderStateDevice::setStencilOps(Face face, const StencilOps& ops) {
  checkFace(face);
  checkStencilOps(ops);
  state_.setStencilOps(face, ops);
  stateChanged(StateChange::StencilOps, face);
}

void RenderStateDevice::setStencilWriteMask(std::uint8_t mask) {
  state_.stencilWriteMask = mask;
  stateChanged(StateChange::StencilWriteMask, Face::Both);
}

void RenderStateDevice::setCullMode(CullMode mode) {
  checkCullMode(mode);
  state_.cull = mode;
  stateChanged(StateChange::CullMode, Face::Both);
}

}  // namespace recode::raster
