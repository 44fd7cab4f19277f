// Command streams as data (command_stream.hpp): what RecordingDevice writes down while it
// forwards, what replay() sends on, and how applyToState follows a stream's state without a
// device.

#include <catch2/catch.hpp>

#include <cstdint>
#include <variant>
#include <vector>

#include "raster_test_support.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"

using namespace recode::raster;

namespace {

// One command of each kind, every field away from its default, so that a field lost on the
// way shows. The draw is a triangle over most of a 7 x 5 framebuffer.
void sendOneOfEach(DepthStencilDevice& dev) {
  dev.setScissor({1, 1, 6, 4});
  dev.clearDepth(0.5);
  dev.clearStencil(0x21);
  dev.setDepthFunc(CompareFunc::GEqual);
  dev.setDepthWriteMask(false);
  dev.setStencilFunc(CompareFunc::NotEqual, 7, 0x3C);
  dev.setStencilOps(Face::Back, {StencilOp::Zero, StencilOp::Invert, StencilOp::DecrWrap});
  dev.setStencilWriteMask(0x0F);
  dev.setCullMode(CullMode::Front);
  recode::test::drawTriangle(dev, {0.0f, 0.0f, 0.25f}, {0.0f, 5.0f, 0.25f}, {7.0f, 0.0f, 0.25f});
}

}  // namespace

TEST_CASE("a recording device writes down the inner device's size and every command in order",
          "[raster][stream]") {
  CpuDevice inner(7, 5);
  RecordingDevice recorder(inner);
  // The stream's size is the inner device's, width and height each (7 x 5: not square).
  CHECK(recorder.stream().width == 7);
  CHECK(recorder.stream().height == 5);
  sendOneOfEach(recorder);
  const std::vector<Command>& c = recorder.stream().commands;
  REQUIRE(c.size() == 10);
  CHECK(std::get<cmd::Scissor>(c[0]).rect == PixelRect{1, 1, 6, 4});
  CHECK(std::get<cmd::ClearDepth>(c[1]).value == 0.5);
  CHECK(std::get<cmd::ClearStencil>(c[2]).value == 0x21);
  CHECK(std::get<cmd::DepthFunc>(c[3]).func == CompareFunc::GEqual);
  CHECK(std::get<cmd::DepthWriteMask>(c[4]).write == false);
  const auto& stencilFunc = std::get<cmd::StencilFunc>(c[5]);
  CHECK(stencilFunc.func == CompareFunc::NotEqual);
  CHECK(stencilFunc.ref == 7);
  CHECK(stencilFunc.valueMask == 0x3C);
  const auto& ops = std::get<cmd::StencilOpsCmd>(c[6]);
  CHECK(ops.face == Face::Back);
  CHECK(ops.ops == StencilOps{StencilOp::Zero, StencilOp::Invert, StencilOp::DecrWrap});
  CHECK(std::get<cmd::StencilWriteMask>(c[7]).mask == 0x0F);
  CHECK(std::get<cmd::Cull>(c[8]).mode == CullMode::Front);
  const auto& draw = std::get<cmd::Draw>(c[9]);
  CHECK(draw.vertices.size() == 3);
  CHECK(draw.indices == std::vector<std::uint32_t>{0, 1, 2});
  // Forwarded too: the inner device took each command.
  const RenderState& s = inner.state();
  CHECK(s.scissor == PixelRect{1, 1, 6, 4});
  CHECK(s.depthFunc == CompareFunc::GEqual);
  CHECK(s.backOps == StencilOps{StencilOp::Zero, StencilOp::Invert, StencilOp::DecrWrap});
  CHECK(s.frontOps == StencilOps{});
  CHECK(s.stencilWriteMask == 0x0F);
  CHECK(s.cull == CullMode::Front);
  // A command the inner device refuses is not written down.
  CHECK_THROWS_AS(recorder.setCullMode(static_cast<CullMode>(3)), std::invalid_argument);
  CHECK(c.size() == 10);
}

TEST_CASE("replaying a recorded stream gives the recording device's buffers and state",
          "[raster][stream]") {
  CpuDevice inner(7, 5);
  RecordingDevice recorder(inner);
  sendOneOfEach(recorder);
  // The triangle (0,0) (0,5) (7,0) is clockwise (twice its area is -35): back-facing, so the
  // front cull keeps it and the back ops apply. Inside the scissor the stencil test NOTEQUAL
  // passes (7 & 0x3C = 4 against 0x21 & 0x3C = 0x20) and the depth test GEQUAL fails (0.25
  // against the cleared 0.5), so the depth-fail op INVERT runs.
  CpuDevice copy(7, 5);
  replay(recorder.stream().commands, copy);
  const PixelRect all{0, 0, 7, 5};
  CHECK(copy.readStencil(all) == inner.readStencil(all));
  CHECK(copy.readDepth(all) == inner.readDepth(all));
  const RenderState& a = copy.state();
  const RenderState& b = inner.state();
  CHECK(a.stencilWriteMask == b.stencilWriteMask);
  CHECK(a.cull == b.cull);
  CHECK(a.backOps == b.backOps);
  CHECK(a.stencilFunc == b.stencilFunc);
  CHECK(a.depthWrite == b.depthWrite);
  // The draw changed some stencil through the write mask: INVERT of 0x21 is 0xDE, of which
  // only the low four bits (0xE) go in, 0x2E; pixel (1, 1) is inside the triangle and scissor.
  CHECK(inner.readStencil({1, 1, 2, 2}).front() == 0x2E);
}

TEST_CASE("applyToState follows every state command as a device does, and no buffer command",
          "[raster][stream]") {
  CpuDevice dev(7, 5);
  RecordingDevice recorder(dev);
  sendOneOfEach(recorder);
  // A state that starts away from every value the stream sets, so each field must change.
  RenderState followed = initialRenderState(7, 5);
  followed.depthWrite = true;
  int stateCommands = 0;
  for (const Command& c : recorder.stream().commands) {
    const bool applied = applyToState(c, followed, 7, 5);
    CHECK(applied == !changesBuffers(c));
    stateCommands += applied;
  }
  CHECK(stateCommands == 7);  // all but the two clears and the draw
  const RenderState& s = dev.state();
  CHECK(followed.scissor == s.scissor);
  CHECK(followed.depthFunc == s.depthFunc);
  CHECK(followed.depthWrite == false);
  CHECK(followed.stencilFunc == s.stencilFunc);
  CHECK(followed.stencilRef == 7);
  CHECK(followed.stencilValueMask == 0x3C);
  CHECK(followed.frontOps == s.frontOps);
  CHECK(followed.backOps == s.backOps);
  CHECK(followed.stencilWriteMask == 0x0F);
  CHECK(followed.cull == CullMode::Front);
  // The scissor clamped to the framebuffer given, as a device clamps it.
  applyToState(cmd::Scissor{{-3, 2, 40, 9}}, followed, 7, 5);
  CHECK(followed.scissor == PixelRect{0, 2, 7, 5});
}
