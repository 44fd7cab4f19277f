// Records the buffers `recode explain` pictures: a PairObserver's snapshots and block coverage.
#include "explain/explain_recorder.hpp"

#include "recode/pair/frame.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::explain {

void StepRecorder::afterStep(core::PairStep step, raster::DepthStencilDevice& device) {
  const raster::PixelRect all{0, 0, device.width(), device.height()};
  std::optional<raster::RenderState> state;
  if (const auto* cpu = dynamic_cast<const raster::CpuDevice*>(&device))
    state = cpu->state();
  snapshots_.push_back(
      {step, raster::readStencilBuffer(device, all), raster::readDepthBuffer(device, all), state});
}

raster::PixelBuffer<std::uint8_t> blockCoverage(const PairSetup& setup, double depthMin,
                                                double depthMax) {
  const core::FrameSpec& f = setup.frame;
  const core::OrthoView view(f.axis, f.window, f.width, f.height, depthMin, depthMax);
  raster::CpuDevice device(f.width, f.height);
  device.setScissor({0, 0, f.width, f.height});
  device.setStencilWriteMask(0xFF);
  device.clearStencil(0);
  device.setDepthWriteMask(false);
  device.setDepthFunc(raster::CompareFunc::Always);
  device.setCullMode(raster::CullMode::None);
  device.setStencilOps(raster::Face::Both, {raster::StencilOp::Keep, raster::StencilOp::Keep,
                                            raster::StencilOp::Replace});
  const auto draw = [&](const core::TriangleMesh& mesh, std::uint8_t bit) {
    device.setStencilFunc(raster::CompareFunc::Always, bit, 0xFF);
    device.setStencilWriteMask(bit);
    const auto vertices = view.toWindow(mesh);
    const auto indices = core::triangleIndices(mesh);
    device.drawTriangles(vertices, indices);
  };
  draw(setup.a, 1);
  draw(setup.b, 2);
  return raster::readStencilBuffer(device, {0, 0, f.width, f.height});
}

FaceDepths faceDepths(const PairSetup& setup, const core::TriangleMesh& mesh, double depthMin,
                      double depthMax) {
  const core::FrameSpec& f = setup.frame;
  const core::OrthoView view(f.axis, f.window, f.width, f.height, depthMin, depthMax);
  const auto vertices = view.toWindow(mesh);
  const auto indices = core::triangleIndices(mesh);
  raster::CpuDevice device(f.width, f.height);
  const raster::PixelRect all{0, 0, f.width, f.height};
  device.setScissor(all);
  device.setStencilWriteMask(0);
  device.setStencilFunc(raster::CompareFunc::Always, 0, 0xFF);
  device.setDepthWriteMask(true);
  const auto surface = [&](raster::CullMode culled, double clear, raster::CompareFunc keep) {
    device.clearDepth(clear);
    device.setCullMode(culled);
    device.setDepthFunc(keep);
    device.drawTriangles(vertices, indices);
    return raster::readDepthBuffer(device, all);
  };
  FaceDepths d;
  d.front = surface(raster::CullMode::Back, 1.0, raster::CompareFunc::LEqual);
  d.back = surface(raster::CullMode::Front, 0.0, raster::CompareFunc::GEqual);
  return d;
}

}  // namespace recode::explain
