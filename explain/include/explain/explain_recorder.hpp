#pragma once
// The buffers `recode explain` pictures: depth and stencil after every step, and block coverage.

#include <cstdint>
#include <optional>
#include <vector>

#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/pixel_buffer.hpp"
#include "recode/raster/state.hpp"

namespace recode::explain {

// Every step is kept as a full-frame copy of both buffers, so the frame is limited to keep
// that (and one picture pixel per framebuffer pixel) reasonable.
inline constexpr int kMaxExplainSide = 2048;

// Both buffers over the whole frame after one step.
struct StepSnapshot {
  core::PairStep step;
  raster::PixelBuffer<std::uint8_t> stencil;
  raster::PixelBuffer<std::uint32_t> depth;
  // The device's state after the step: the state its draws ran with, since every step sets
  // all the state they depend on (docs/algorithm.md section 3). Empty on a device that does
  // not show its state.
  std::optional<raster::RenderState> state;
};

// Keeps a full-frame copy of the stencil and depth buffers after every step of the pair
// algorithm.
class StepRecorder final : public core::PairObserver {
 public:
  void afterStep(core::PairStep step, raster::DepthStencilDevice& device) override;
  [[nodiscard]] const std::vector<StepSnapshot>& snapshots() const { return snapshots_; }

 private:
  std::vector<StepSnapshot> snapshots_;
};

// Coverage of A (bit 0) and B (bit 1) over the whole frame, drawn through
// the device interface on a device of its own: depth test ALWAYS, no depth writes, each
// block setting its own stencil bit. [depthMin, depthMax] is the world range along the view
// axis that the view maps onto depth.
[[nodiscard]] raster::PixelBuffer<std::uint8_t> blockCoverage(const PairSetup& setup,
                                                              double depthMin, double depthMax);

// Where one block's surface lies along every pixel's ray, drawn on a device of its own with
// the view of the pair: the nearest front-facing fragment (back faces culled, LEQUAL from a
// clear to 1) and the farthest back-facing one (front faces culled, GEQUAL from a clear to 0),
// the very fragments the Amin tests of steps 4 and 5 compare. Pixels without such a face keep
// the clear value.
struct FaceDepths {
  raster::PixelBuffer<std::uint32_t> front;  // kDepthMax where no front face
  raster::PixelBuffer<std::uint32_t> back;   // 0 where no back face
};
[[nodiscard]] FaceDepths faceDepths(const PairSetup& setup, const core::TriangleMesh& mesh,
                                    double depthMin, double depthMax);

}  // namespace recode::explain
