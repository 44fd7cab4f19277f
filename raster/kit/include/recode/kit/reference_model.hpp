#pragma once
// An independent, deliberately naive model of the depth/stencil machine, written from
// docs/rasterization.md rather than from the device code: every pixel centre of the scissor
// is tested against every triangle with direct cross products, and the per-fragment stage is
// written out longhand. The tests hold raster::CpuDevice (tiles, blocks, incremental edge
// stepping) against it bit for bit.
//
// It also runs the contract's likely misreadings (variants.hpp), one at a time, so that the
// conformance kit can prove each one is caught by some golden vector.

#include <cstdint>
#include <vector>

#include "recode/kit/variants.hpp"
#include "recode/raster/command_stream.hpp"

namespace recode::kit {

class ReferenceModel {
 public:
  ReferenceModel(int width, int height, Variant variant = Variant::Contract);

  // Throws std::invalid_argument where the variant's validation refuses a draw (StrictLimits).
  void run(const std::vector<raster::Command>& commands);

  [[nodiscard]] std::uint8_t stencil(int x, int y) const { return stencil_[idx(x, y)]; }
  [[nodiscard]] std::uint32_t depth(int x, int y) const { return depth_[idx(x, y)]; }
  [[nodiscard]] const std::vector<std::uint8_t>& stencilBuffer() const { return stencil_; }
  [[nodiscard]] const std::vector<std::uint32_t>& depthBuffer() const { return depth_; }

 private:
  // A triangle's snapped vertices in the submitted order.
  struct Triangle {
    long long X[3], Y[3];
    float Z[3];
  };

  [[nodiscard]] std::size_t idx(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x);
  }
  void clearDepth(double value);
  void clearStencil(unsigned value);
  void draw(const raster::cmd::Draw& d);
  void drawTriangle(const Triangle& t);
  [[nodiscard]] bool covers(const Triangle& t, const int order[3], long long px,
                            long long py) const;
  void fragment(int x, int y, bool front, std::uint32_t z);
  [[nodiscard]] std::uint32_t quantize(double z) const;
  [[nodiscard]] unsigned stencilOp(int op, unsigned s) const;

  int w_, h_;
  Variant variant_;
  std::vector<std::uint32_t> depth_;
  std::vector<std::uint8_t> stencil_;
  // State, GL defaults.
  int sx0_ = 0, sy0_ = 0, sx1_, sy1_;
  int depthFunc_ = 1;  // LESS
  bool depthWrite_ = true;
  int stencilFunc_ = 7;  // ALWAYS
  unsigned ref_ = 0, valueMask_ = 255, writeMask_ = 255;
  int opsFront_[3] = {0, 0, 0}, opsBack_[3] = {0, 0, 0};
  int cull_ = 0;
};

// Longhand versions of the GL tables, by numeric code in GL's order (NEVER LESS EQUAL LEQUAL
// GREATER NOTEQUAL GEQUAL ALWAYS; KEEP ZERO REPLACE INCR INCR_WRAP DECR DECR_WRAP INVERT).
bool modelCompare(int func, unsigned incoming, unsigned stored);
unsigned modelStencilOp(int op, unsigned s, unsigned ref);
std::uint32_t modelQuantize(double z);

}  // namespace recode::kit
