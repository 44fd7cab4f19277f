#pragma once
// The per-pixel data of the ray inspector: depth and stencil after every step, both blocks'
// face depths and the case, over the MOR plus a margin, embedded in index.html as JSON.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "explain/explain_recorder.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/pixel_buffer.hpp"

namespace recode::explain {

// At most this many pixels of ray data go into the page (8 steps x 2 buffers each, about
// 2.5 MB of JSON at the limit); a larger crop is cut to a window around where both blocks are.
inline constexpr int kMaxRayPixels = 16384;

struct RayInputs {
  const core::PairResult& result;
  const std::vector<StepSnapshot>& snapshots;
  const raster::PixelBuffer<std::uint8_t>& coverage;  // bit 0: A, bit 1: B
  const FaceDepths& a;
  const FaceDepths& b;
  double depthMin = 0.0;  // world range along the view axis that depth 0..1 spans
  double depthMax = 1.0;
};

// The MOR with a margin (empty when the MOR is), inside the frame.
[[nodiscard]] raster::PixelRect morWithMargin(const raster::PixelRect& mor,
                                              const raster::PixelRect& frame);

// The pixels the inspector has data for: the MOR with a margin, cut to kMaxRayPixels around
// the pixels both blocks cover. Empty when there is no MOR.
[[nodiscard]] raster::PixelRect rayCrop(const RayInputs& in, const raster::PixelRect& frame);

// The inspector's data with its per-pixel arrays apart from the rest: each array row by row,
// bottom row first, over the crop, crop.area() values.
struct RayArrays {
  nlohmann::json scalars;  // "frame", "crop", "capped", "steps": [{"id"}], "mor",
                           // "step_words": [{"id", "name", "rule", "operands"}] of every
                           // step (explain_text.hpp's stepWords, stepOperands), ...
  std::vector<std::vector<std::uint32_t>> depth;    // after each step
  std::vector<std::vector<std::uint32_t>> stencil;  // after each step
  std::vector<std::uint32_t> aFront, aBack, bFront, bBack, coverage;
  std::vector<std::int32_t> cases;  // -1 outside the MOR
};
[[nodiscard]] RayArrays rayArrays(const RayInputs& in, const raster::PixelRect& frame,
                                  const raster::PixelRect& crop);

// {"crop", "capped", "steps": [{"id"}], "depth": [[...]], "stencil": [[...]], "a_front",
// "a_back", "b_front", "b_back", "coverage", "case", ...}: the arrays and the rest as one JSON
// object (the inline data of `recode explain`'s page).
[[nodiscard]] nlohmann::json rayDataJson(RayArrays arrays);

// Calls f(name, values) for every per-pixel array of `r`, in the one order both pages read
// them by name: "depth" and "stencil" (one array per step), "a_front", "a_back", "b_front",
// "b_back", "coverage", "case". The static page's JSON keys and the WebAssembly page's block
// of numbers ("ray_arrays.order") both follow it.
template <class F>
void forEachRayArray(const RayArrays& r, F&& f) {
  f("depth", r.depth);
  f("stencil", r.stencil);
  f("a_front", r.aFront);
  f("a_back", r.aBack);
  f("b_front", r.bFront);
  f("b_back", r.bBack);
  f("coverage", r.coverage);
  f("case", r.cases);
}

}  // namespace recode::explain
