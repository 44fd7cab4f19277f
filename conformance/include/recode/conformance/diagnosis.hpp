#pragma once
// Why a back end's answer differs from the contract's: for a differing pixel, the stage of the
// contract that first goes another way (coverage, facing, depth value, quantisation, depth
// test, stencil, clears, validation) and the section of docs/rasterization.md that states its
// rule; for a whole run, the kit's wrong readings (kit/variants.hpp) whose answers equal the
// back end's on every vector ("behaves like: the plane evaluated with a fused multiply-add");
// and for a vector, whether the graphics APIs themselves require its answer or only this
// contract does.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "recode/conformance/backend.hpp"
#include "recode/conformance/pixel_history.hpp"
#include "recode/conformance/stage.hpp"
#include "recode/kit/variants.hpp"
#include "recode/raster/command_stream.hpp"

namespace recode::conformance {

// The stage a wrong reading of the kit departs at (top_left_fill: coverage, fma_plane: depth
// value, quantise_truncate: quantisation, ...).
[[nodiscard]] Stage stageOf(kit::Variant v);

// A pixel where the back end's buffers differ from the expected ones.
struct BadPixel {
  int x = 0, y = 0;  // GL window coordinates
  std::uint32_t expectedDepth = 0, gotDepth = 0;
  std::uint8_t expectedStencil = 0, gotStencil = 0;
  [[nodiscard]] bool depthDiffers() const { return expectedDepth != gotDepth; }
  [[nodiscard]] bool stencilDiffers() const { return expectedStencil != gotStencil; }
  // gotDepth - expectedDepth, in 24-bit depth units.
  [[nodiscard]] long long depthUnits() const {
    return static_cast<long long>(gotDepth) - static_cast<long long>(expectedDepth);
  }
};

// Every differing pixel in scan order (row 0 first), at most `limit`; `count` gets their number.
[[nodiscard]] std::vector<BadPixel> badPixels(const raster::CommandStream& stream,
                                              const Answer& expected, const Answer& got,
                                              std::size_t limit, long long* count = nullptr);

// A bad pixel explained: its history under the contract, the stage that first differs and why.
struct PixelExplanation {
  BadPixel pixel;
  PixelHistory history;
  Stage stage = Stage::DepthValue;
  std::string why;  // one sentence, e.g. "the back end kept the clear's depth where triangle 3
                    // of draw 0 covers the sample on its inclusive left edge"
  // A wrong reading whose model gives the back end's values at this pixel, if any.
  std::optional<kit::Variant> sameAsReading;
  // The name of the stage rule that read the history (e.g. "no trace of a fragment", "a depth
  // the history holds"); the stage is the reading's instead when one gives it (see explainPixel).
  std::string_view rule;
};

// `readings`: the wrong readings' answers to the same stream (from readingAnswers), consulted
// to name the stage; may be empty.
struct ReadingAnswer {
  kit::Variant variant;
  Answer answer;
};
[[nodiscard]] std::vector<ReadingAnswer> readingAnswers(const raster::CommandStream& stream);

// Explains a bad pixel. Its stage is read from its history by ordered rules, the first that
// applies winning: buffers that hold the pixel's values from just before an event that changes
// it show no trace of that event (coverage for a fragment, clear for a clear, never a test that
// went the other way); then clears outside the scissor or through a write mask; then a stencil
// or depth test that went the other way, found by replaying the history with the comparisons
// free (the first fragment whose test must go the other way for the back end's values to be
// reached); then rounding ties, edges, culling, the depth value, the depth test and the
// stencil. A reading of the kit that gives the back end's values is named in `why` but does not
// decide the stage: only a whole run that behaves like it does (attributeToReading).
[[nodiscard]] PixelExplanation explainPixel(const raster::CommandStream& stream,
                                            const BadPixel& pixel,
                                            const std::vector<ReadingAnswer>& readings);

// Attributes an explained pixel to a reading known to give the back end's values there (the one
// a whole run behaves like): its stage, and why, with the history's own account when it agrees.
void attributeToReading(PixelExplanation& e, kit::Variant v);

// The stage at which a whole failing answer first departs: a refusal is Validation; else the
// stage of its first bad pixel.
[[nodiscard]] Stage failingStage(const raster::CommandStream& stream, const Answer& expected,
                                 const Answer& got, const std::vector<ReadingAnswer>& readings);

// Whether the graphics APIs (Vulkan, OpenGL, WebGPU) fix a vector's answer, buffer by buffer:
// a buffer is fixed when the APIs allow every pixel of it exactly one value (api_freedoms.hpp;
// api_verdict.hpp's requirementOf computes it), else `latitudes` names the APIs' freedoms that
// leave some pixel open.
struct BufferRequirement {
  bool byGraphicsApis = true;
  std::vector<std::string> latitudes;  // "the tie rule", "the sub-pixel precision", ...
};
// Both buffers' requirements.
struct Requirement {
  BufferRequirement depth, stencil;
  // Whether the APIs fix both buffers.
  [[nodiscard]] bool byGraphicsApis() const {
    return depth.byGraphicsApis && stencil.byGraphicsApis;
  }
};

}  // namespace recode::conformance
