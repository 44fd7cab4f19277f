// Stencil and depth operations on single pixels, exhaustively over compare functions, stencil
// ops, masks, stored values and facing, against the longhand model of reference_model.cpp.

#include <catch2/catch.hpp>
#include <cmath>

#include "raster_test_support.hpp"
#include "recode/kit/reference_model.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/fragment_stage.hpp"

using namespace recode::raster;
using recode::kit::modelCompare;
using recode::kit::modelQuantize;
using recode::kit::modelStencilOp;

namespace {

// A 1x1 framebuffer; the triangle covers the single pixel centre (0.5, 0.5) at constant depth.
cmd::Draw pixelDraw(float z, bool front) {
  cmd::Draw d{{{-1.0f, -1.0f, z}, {3.0f, -1.0f, z}, {-1.0f, 3.0f, z}}, {0, 1, 2}};
  if (!front)
    std::swap(d.indices[1], d.indices[2]);
  return d;
}

}  // namespace

TEST_CASE("compare functions and stencil ops match the GL tables", "[fragment]") {
  for (int f = 0; f < 8; ++f) {
    for (unsigned a : {0u, 1u, 7u, 255u}) {
      for (unsigned b : {0u, 1u, 7u, 255u}) {
        CHECK(compare(static_cast<CompareFunc>(f), a, b) == modelCompare(f, a, b));
      }
    }
  }
  for (int op = 0; op < 8; ++op) {
    for (unsigned s = 0; s < 256; ++s) {
      for (unsigned ref : {0u, 1u, 128u, 255u}) {
        REQUIRE(applyStencilOp(static_cast<StencilOp>(op), static_cast<std::uint8_t>(s),
                               static_cast<std::uint8_t>(ref)) == modelStencilOp(op, s, ref));
      }
    }
  }
  // Spot values written out by hand: saturation versus wrap.
  CHECK(applyStencilOp(StencilOp::Incr, 255, 0) == 255);
  CHECK(applyStencilOp(StencilOp::IncrWrap, 255, 0) == 0);
  CHECK(applyStencilOp(StencilOp::Decr, 0, 0) == 0);
  CHECK(applyStencilOp(StencilOp::DecrWrap, 0, 0) == 255);
  CHECK(applyStencilOp(StencilOp::Invert, 0x5A, 0) == 0xA5);
  CHECK(applyStencilOp(StencilOp::Replace, 3, 77) == 77);
}

TEST_CASE("single-pixel fragments: every func x op x mask x value combination", "[fragment]") {
  const float storedZ = 0.5f;
  const std::uint32_t stored = modelQuantize(storedZ);
  // Incoming depths one quantisation step below, equal to and above the stored value.
  const float incoming[3] = {std::nextafter(storedZ, 0.0f) - 1e-7f, storedZ,
                             std::nextafter(storedZ, 1.0f) + 1e-7f};
  REQUIRE(modelQuantize(incoming[0]) < stored);
  REQUIRE(modelQuantize(incoming[1]) == stored);
  REQUIRE(modelQuantize(incoming[2]) > stored);

  const std::uint8_t refs[] = {0, 1, 0x80, 0xFF, 0x5A};
  const std::uint8_t valueMasks[] = {0xFF, 0x0F, 0xF0, 0x00};
  const std::uint8_t writeMasks[] = {0xFF, 0x0F, 0x00};
  const std::uint8_t initial[] = {0, 1, 0x7F, 0x80, 0xFE, 0xFF};
  // One stream per combination on a fresh 1x1 framebuffer: set the pixel, set the state under
  // test, draw one fragment (the other face gets KEEP everywhere). The device and the longhand
  // model must agree.
  std::vector<Command> stream(9);
  long long checked = 0;
  for (int sf = 0; sf < 8; ++sf) {
    for (int df = 0; df < 8; ++df) {
      for (int op = 0; op < 8; ++op) {
        // Three different ops per combination so that the branch taken is visible.
        const StencilOps under{static_cast<StencilOp>(op), static_cast<StencilOp>((op + 3) % 8),
                               static_cast<StencilOp>((op + 5) % 8)};
        for (std::uint8_t ref : refs) {
          for (std::uint8_t vm : valueMasks) {
            for (std::uint8_t wm : writeMasks) {
              for (std::uint8_t s0 : initial) {
                for (const float z : incoming) {
                  for (const bool depthWrite : {true, false}) {
                    for (const bool front : {true, false}) {
                      stream[0] = cmd::ClearStencil{s0};
                      stream[1] = cmd::ClearDepth{storedZ};
                      stream[2] = cmd::DepthFunc{static_cast<CompareFunc>(df)};
                      stream[3] = cmd::DepthWriteMask{depthWrite};
                      stream[4] = cmd::StencilFunc{static_cast<CompareFunc>(sf), ref, vm};
                      stream[5] = cmd::StencilOpsCmd{front ? Face::Front : Face::Back, under};
                      stream[6] = cmd::StencilOpsCmd{front ? Face::Back : Face::Front, {}};
                      stream[7] = cmd::StencilWriteMask{wm};
                      stream[8] = pixelDraw(z, front);
                      CpuDevice dev(1, 1);
                      replay(stream, dev);
                      recode::kit::ReferenceModel model(1, 1);
                      model.run(stream);
                      if (dev.stencilBuffer()[0] != model.stencil(0, 0) ||
                          dev.depthBuffer()[0] != model.depth(0, 0)) {
                        FAIL("sf " << sf << " df " << df << " op " << op << " ref " << int(ref)
                                   << " vm " << int(vm) << " wm " << int(wm) << " s0 " << int(s0)
                                   << " z " << z << " front " << front << ": got s "
                                   << int(dev.stencilBuffer()[0]) << " d " << dev.depthBuffer()[0]
                                   << ", model s " << int(model.stencil(0, 0)) << " d "
                                   << model.depth(0, 0));
                      }
                      ++checked;
                    }
                  }
                }
              }
            }
          }
        }
      }
    }
  }
  CHECK(checked == 8LL * 8 * 8 * 5 * 4 * 3 * 6 * 3 * 2 * 2);
}

TEST_CASE("the model's fragment stage on hand-worked examples", "[fragment]") {
  // The model is itself checked on cases worked out by hand, so that device and model cannot
  // agree on a shared mistake unnoticed.
  const auto run = [](std::vector<Command> cmds) {
    recode::kit::ReferenceModel m(1, 1);
    m.run(cmds);
    return std::make_pair(int(m.stencil(0, 0)), m.depth(0, 0));
  };
  const std::uint32_t half = 8388608u;  // quantised 0.5
  // Stencil test fails (ref 2 LESS stored 1 is false): sfail = REPLACE writes ref 2; depth kept.
  CHECK(
      run({cmd::ClearStencil{1}, cmd::ClearDepth{1.0}, cmd::StencilFunc{CompareFunc::Less, 2, 0xFF},
           cmd::StencilOpsCmd{Face::Both, {StencilOp::Replace, StencilOp::Zero, StencilOp::Keep}},
           pixelDraw(0.5f, true)}) == std::make_pair(2, 16777215u));
  // Stencil passes, depth fails (0.5 LESS 0.25 is false): dpfail = INCR; depth kept.
  CHECK(run({cmd::ClearStencil{7}, cmd::ClearDepth{0.25},
             cmd::StencilOpsCmd{Face::Front, {StencilOp::Zero, StencilOp::Incr, StencilOp::Zero}},
             pixelDraw(0.5f, true)}) == std::make_pair(8, 4194304u));
  // Both pass: dppass = INVERT through write mask 0x0F, depth written.
  CHECK(run({cmd::ClearStencil{0x35}, cmd::StencilWriteMask{0x0F},
             cmd::StencilOpsCmd{Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert}},
             pixelDraw(0.5f, true)}) == std::make_pair(0x3A, half));
  // Back face uses the back ops; value mask 0xF0 hides the low bits (ref 0x1F & 0xF0 = 0x10
  // EQUAL stored 0x13 & 0xF0 = 0x10 passes).
  CHECK(
      run({cmd::ClearStencil{0x13}, cmd::StencilFunc{CompareFunc::Equal, 0x1F, 0xF0},
           cmd::StencilOpsCmd{Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::Zero}},
           cmd::StencilOpsCmd{Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::DecrWrap}},
           pixelDraw(0.5f, false)}) == std::make_pair(0x12, half));
}
