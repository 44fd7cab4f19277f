// Stencil and depth operations on single pixels, exhaustively over compare functions, stencil
// ops, masks, stored values and facing, against the longhand model of reference_model.cpp.

#include <catch2/catch.hpp>
#include <cmath>

#include "raster_test_support.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "reference_model.hpp"

using namespace recode::raster;
using recode::test::modelCompare;
using recode::test::modelQuantize;
using recode::test::modelStencilOp;

namespace {

// A 1x1 framebuffer; the triangle covers the single pixel centre (0.5, 0.5) at constant depth.
void drawPixel(CpuDevice& dev, float z, bool front) {
  const WindowVertex a{-1.0f, -1.0f, z}, b{3.0f, -1.0f, z}, c{-1.0f, 3.0f, z};
  if (front) {
    recode::test::drawTriangle(dev, a, b, c);
  } else {
    recode::test::drawTriangle(dev, a, c, b);
  }
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
  long long checked = 0;
  CpuDevice dev(1, 1);
  for (int sf = 0; sf < 8; ++sf) {
    for (int df = 0; df < 8; ++df) {
      for (int op = 0; op < 8; ++op) {
        // Three different ops per combination so that the branch taken is visible.
        const int ops[3] = {op, (op + 3) % 8, (op + 5) % 8};
        for (std::uint8_t ref : refs) {
          for (std::uint8_t vm : valueMasks) {
            for (std::uint8_t wm : writeMasks) {
              for (std::uint8_t s0 : initial) {
                for (const float z : incoming) {
                  for (const bool depthWrite : {true, false}) {
                    for (const bool front : {true, false}) {
                      // Reset the pixel.
                      dev.setStencilWriteMask(0xFF);
                      dev.setDepthWriteMask(true);
                      dev.clearStencil(s0);
                      dev.clearDepth(storedZ);
                      // State under test; the other face gets KEEP everywhere.
                      dev.setDepthFunc(static_cast<CompareFunc>(df));
                      dev.setDepthWriteMask(depthWrite);
                      dev.setStencilFunc(static_cast<CompareFunc>(sf), ref, vm);
                      const StencilOps under{static_cast<StencilOp>(ops[0]),
                                             static_cast<StencilOp>(ops[1]),
                                             static_cast<StencilOp>(ops[2])};
                      dev.setStencilOps(front ? Face::Front : Face::Back, under);
                      dev.setStencilOps(front ? Face::Back : Face::Front, StencilOps{});
                      dev.setStencilWriteMask(wm);
                      drawPixel(dev, z, front);

                      // The model, written out.
                      const std::uint32_t q = modelQuantize(z);
                      unsigned s = s0;
                      std::uint32_t d = stored;
                      int taken;
                      if (!modelCompare(sf, ref & vm, s & vm)) {
                        taken = ops[0];
                      } else if (!modelCompare(df, q, d)) {
                        taken = ops[1];
                      } else {
                        taken = ops[2];
                        if (depthWrite)
                          d = q;
                      }
                      s = (modelStencilOp(taken, s, ref) & wm) | (s & (255u - wm));
                      if (dev.stencilBuffer()[0] != s || dev.depthBuffer()[0] != d) {
                        FAIL("sf " << sf << " df " << df << " ops " << ops[0] << ops[1] << ops[2]
                                   << " ref " << int(ref) << " vm " << int(vm) << " wm " << int(wm)
                                   << " s0 " << int(s0) << " z " << z << " front " << front
                                   << ": got s " << int(dev.stencilBuffer()[0]) << " d "
                                   << dev.depthBuffer()[0] << ", want s " << s << " d " << d);
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
