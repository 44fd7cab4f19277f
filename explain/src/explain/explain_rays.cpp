// The per-pixel data of the ray inspector, cropped and bounded.
#include "explain/explain_rays.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "explain/explain_text.hpp"
#include "recode/pair/pair_cases.hpp"

namespace recode::explain {

namespace {

using raster::PixelRect;

nlohmann::json rectJson(const PixelRect& r) {
  return nlohmann::json::array({r.x0, r.y0, r.x1, r.y1});
}

template <class T>
std::vector<std::uint32_t> cropped(const raster::PixelBuffer<T>& buffer, const PixelRect& crop) {
  std::vector<std::uint32_t> values;
  values.reserve(static_cast<std::size_t>(crop.area()));
  for (int y = crop.y0; y < crop.y1; ++y)
    for (int x = crop.x0; x < crop.x1; ++x)
      values.push_back(buffer.at(x, y));
  return values;
}

// The rectangle of pixels both blocks cover, or the MOR when there is none.
PixelRect whereBothAre(const RayInputs& in) {
  const PixelRect& m = in.result.mor;
  PixelRect c{m.x1, m.y1, m.x0, m.y0};
  for (int y = m.y0; y < m.y1; ++y)
    for (int x = m.x0; x < m.x1; ++x)
      if ((in.coverage.at(x, y) & 3u) == 3u)
        c = {std::min(c.x0, x), std::min(c.y0, y), std::max(c.x1, x + 1), std::max(c.y1, y + 1)};
  return c.empty() ? m : c;
}

}  // namespace

// The MOR with a margin of an eighth of its longer side (at least 2 pixels).
PixelRect morWithMargin(const PixelRect& m, const PixelRect& frame) {
  if (m.empty())
    return {};
  const int margin = std::max(2, std::max(m.width(), m.height()) / 8);
  return PixelRect{m.x0 - margin, m.y0 - margin, m.x1 + margin, m.y1 + margin}.intersect(frame);
}

PixelRect rayCrop(const RayInputs& in, const PixelRect& frame) {
  const PixelRect crop = morWithMargin(in.result.mor, frame);
  if (crop.empty() || crop.area() <= kMaxRayPixels)
    return crop;
  // Too many: a window of at most kMaxRayPixels centred on where both blocks are.
  const PixelRect focus = whereBothAre(in);
  const int w = std::min(crop.width(), 128);
  const int h = std::min(crop.height(), kMaxRayPixels / w);
  const int cx = (focus.x0 + focus.x1) / 2, cy = (focus.y0 + focus.y1) / 2;
  const int x0 = std::clamp(cx - w / 2, crop.x0, crop.x1 - w);
  const int y0 = std::clamp(cy - h / 2, crop.y0, crop.y1 - h);
  return {x0, y0, x0 + w, y0 + h};
}

RayArrays rayArrays(const RayInputs& in, const PixelRect& frame, const PixelRect& crop) {
  RayArrays r;
  nlohmann::json& j = r.scalars;
  j["frame"] = rectJson(frame);
  j["crop"] = rectJson(crop);
  j["capped"] = crop != morWithMargin(in.result.mor, frame);
  j["max_pixels"] = kMaxRayPixels;
  j["mor"] = rectJson(in.result.mor);
  j["contact_rect"] = rectJson(in.result.contactRect);
  j["depth_max"] = raster::kDepthMax;
  j["depth_range"] = {in.depthMin, in.depthMax};
  nlohmann::json steps = nlohmann::json::array();
  for (const StepSnapshot& s : in.snapshots) {
    steps.push_back({{"id", std::string(core::toString(s.step))}});
    r.depth.push_back(cropped(s.depth, crop));
    r.stencil.push_back(cropped(s.stencil, crop));
  }
  j["steps"] = steps;
  r.aFront = cropped(in.a.front, crop);
  r.aBack = cropped(in.a.back, crop);
  r.bFront = cropped(in.b.front, crop);
  r.bBack = cropped(in.b.back, crop);
  r.coverage = cropped(in.coverage, crop);
  const PixelRect& m = in.result.mor;
  for (int y = crop.y0; y < crop.y1; ++y)
    for (int x = crop.x0; x < crop.x1; ++x) {
      const bool inMor = x >= m.x0 && x < m.x1 && y >= m.y0 && y < m.y1;
      r.cases.push_back(inMor ? int{in.result.caseMap.at(x, y)} : -1);
    }
  nlohmann::json names = nlohmann::json::array();
  for (int c = 0; c < core::kCaseCount; ++c)
    names.push_back(std::string(core::caseName(c)));
  j["case_names"] = names;
  // Every step's name and rule (whether it ran or not: the interactive page's exercises and
  // terms name the passes a box test skipped), so that the scripts state none of them.
  nlohmann::json words = nlohmann::json::array();
  for (int k = 0; k < core::kPairStepCount; ++k) {
    const auto step = static_cast<core::PairStep>(k);
    const StepWords w = stepWords(step);
    nlohmann::json operands = nlohmann::json::array();
    for (const std::string_view o : stepOperands(step))
      operands.push_back(std::string(o));
    words.push_back({{"id", std::string(core::toString(step))},
                     {"name", std::string(w.name)},
                     {"rule", std::string(w.rule)},
                     {"operands", operands}});
  }
  j["step_words"] = words;
  return r;
}

nlohmann::json rayDataJson(RayArrays r) {
  nlohmann::json j = std::move(r.scalars);
  forEachRayArray(
      r, [&j](std::string_view name, const auto& values) { j[std::string(name)] = values; });
  return j;
}

}  // namespace recode::explain
