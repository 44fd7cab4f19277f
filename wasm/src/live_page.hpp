#pragma once
// What the interactive page shows after every change of the scene or the options: the pair's
// JSON (as `recode pair --json` prints it), the explain page's body for this run (the same
// sections, text and legends as `recode explain`), the ray inspector's data, and the pictures,
// kept in memory at one picture pixel per framebuffer pixel.

#include <cstdint>
#include <string>
#include <vector>

#include "explain/explain_pictures.hpp"
#include "pair_request.hpp"

namespace recode::wasm {

struct LivePage {
  // {"pair", "body", "ray_data", "scene3d" (explain/scene_view.hpp), "ray_arrays": {"offset",
  // "pixels", "order": [{"name", "per_step"}]}, "pictures": [{"file", "width", "height",
  // "offset"}]}; an offset is where the data lies in the module's memory: the ray inspector's
  // per-pixel arrays as 32-bit integers, a picture's RGB bytes (rows from the top).
  std::string json;
  std::vector<explain::KeptPicture> pictures;  // what the pictures' offsets point into
  std::vector<std::int32_t> rays;              // what ray_arrays.offset points into
};

// Runs the pair of the request on the CPU device, recording every step. Throws what loading
// the scene throws, and std::invalid_argument for a frame over the explain page's limit.
[[nodiscard]] LivePage livePage(const PairRequestText& request);

}  // namespace recode::wasm
