#pragma once
// The output of `recode pair`: the JSON object of docs/cli.md ("recode pair") and the report.

#include <nlohmann/json.hpp>
#include <ostream>

#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"

namespace recode::explain {

// Parts of the object, shared with the layered pair's (layered_report.hpp): a pixel rectangle
// [x0, y0, x1, y1]; the `contact` object; the `frame` object.
[[nodiscard]] nlohmann::ordered_json pixelRectJson(const raster::PixelRect& rect);
[[nodiscard]] nlohmann::ordered_json contactRegionJson(const core::ContactRegion& contact);
[[nodiscard]] nlohmann::ordered_json frameJson(const core::FrameSpec& frame, double depthMin,
                                               double depthMax);

// The keys from `mor_mode` to `objects`, in that order, which both pairs' objects have after
// their own (`Result`: core::PairResult or core::LayeredPairResult, whose fields of these names
// mean the same).
template <class Result>
void addRunKeys(nlohmann::ordered_json& j, const PairSetup& setup, const core::PairRequest& request,
                const Result& r) {
  j["mor_mode"] = core::toString(request.mor);
  j["boxes_overlap"] = r.boxesOverlap;
  j["stencil_pixels_read"] = r.stencilPixelsRead;
  j["depth_pixels_read"] = r.depthPixelsRead;
  j["contact_rect"] = pixelRectJson(r.contactRect);
  j["frame"] = frameJson(setup.frame, r.depthMin, r.depthMax);
  j["objects"] = nlohmann::ordered_json::array({setup.nameA, setup.nameB});
}

// The object printed by `recode pair --json` (keys documented in docs/cli.md).
[[nodiscard]] nlohmann::ordered_json pairResultToJson(const PairSetup& setup,
                                                      const core::PairRequest& request,
                                                      const core::PairResult& result);

// Records one pixel's depth and stencil after every step, for `recode pair --pixel X,Y`: an
// independent read of the device (one pixel at a time) that `recode explain`'s ray inspector
// can be checked against.
class PixelProbe final : public core::PairObserver {
 public:
  PixelProbe(int x, int y) : x_(x), y_(y) {}
  void afterStep(core::PairStep step, raster::DepthStencilDevice& device) override;
  // {"x", "y", "case" (null outside the MOR), "steps": {step: {"depth", "stencil"}}}.
  [[nodiscard]] nlohmann::ordered_json toJson(const core::PairResult& result) const;

 private:
  int x_, y_;
  nlohmann::ordered_json steps_ = nlohmann::ordered_json::object();
};

// The human-readable report; `picture` adds a character picture of the MOR's cases.
void printPairReport(std::ostream& out, const PairSetup& setup, const core::PairRequest& request,
                     const core::PairResult& result, bool picture);

// The whole frame's cases for --dump-cases: case 0-8 inside the MOR, 255 outside it (not
// examined), rows bottom-up as the device stores them.
[[nodiscard]] std::vector<std::uint8_t> frameCaseImage(const core::FrameSpec& frame,
                                                       const core::PairResult& result);

}  // namespace recode::explain
