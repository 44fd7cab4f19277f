#include "recode/conformance/api_verdict.hpp"

#include <algorithm>

namespace recode::conformance {

namespace {

// At most this many of a pixel's open choices in a report line; the JSON has them all.
constexpr std::size_t kChoicesShown = 3;

std::string allowedStencils(const std::vector<AllowedState>& states) {
  std::string out;
  for (std::size_t i = 0; i < states.size(); ++i)
    out += (i == 0 ? "" : (i + 1 == states.size() ? " or " : ", ")) +
           std::to_string(static_cast<unsigned>(states[i].stencil));
  return out;
}

std::string allowedDepths(const std::vector<AllowedState>& states) {
  std::string out;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const AllowedState& s = states[i];
    out += (i == 0 ? "" : "; ") + std::to_string(s.depthLo);
    if (s.depthHi != s.depthLo)
      out += " .. " + std::to_string(s.depthHi);
    if (states.size() > 1)
      out += " (with stencil " + std::to_string(static_cast<unsigned>(s.stencil)) + ")";
  }
  return out;
}

}  // namespace

Requirement requirementOf(const AllowedFrame& frame) {
  Requirement r;
  FreedomSet depth = 0, stencil = 0;
  for (const AllowedPixel& p : frame.pixels) {
    if (!p.depthFixed()) {
      r.depth.byGraphicsApis = false;
      for (const AllowedState& s : p.states)
        depth |= s.freedoms;
    }
    if (!p.stencilFixed()) {
      r.stencil.byGraphicsApis = false;
      for (const AllowedState& s : p.states)
        stencil |= s.freedoms;
    }
  }
  const auto names = [](FreedomSet set) {
    std::vector<std::string> out;
    for (Freedom f : {Freedom::TieRule, Freedom::SubPixelPrecision, Freedom::DepthInterpolation,
                      Freedom::DepthConversion})
      if ((set & static_cast<FreedomSet>(f)) != 0)
        out.emplace_back(toString(f));
    return out;
  };
  r.depth.latitudes = names(depth);
  r.stencil.latitudes = names(stencil);
  return r;
}

ApiTally tallyByApis(const AllowedFrame& frame, const std::vector<BadPixel>& bad) {
  ApiTally t;
  for (const BadPixel& p : bad) {
    const AllowedPixel& a = frame.at(p.x, p.y);
    if (a.allows(p.gotDepth, p.gotStencil)) {
      ++t.withinFreedom;
      t.freedoms |= a.freedomsFor(p.gotDepth, p.gotStencil);
    } else {
      ++t.forbidden;
    }
  }
  return t;
}

ApiVerdict judgeByApis(const raster::CommandStream& stream, const BadPixel& pixel,
                       const FreedomWidths& widths) {
  ApiVerdict v;
  const AllowedPixel a = allowedAt(stream, pixel.x, pixel.y, &v.choices, widths);
  v.states = a.states;
  v.depthAllowed = a.allowsDepth(pixel.gotDepth);
  v.stencilAllowed = a.allowsStencil(pixel.gotStencil);
  v.allowed = a.allows(pixel.gotDepth, pixel.gotStencil);
  v.freedoms = a.freedomsFor(pixel.gotDepth, pixel.gotStencil);
  return v;
}

std::string_view apiClause(Stage stage) {
  switch (stage) {
    case Stage::Coverage:
      return "a sample farther from every edge than snapping reaches is inside or outside on "
             "every allowed grid (Vulkan, Basic Polygon Rasterization; OpenGL 4.5 section "
             "14.6.1)";
    case Stage::Facing:
      return "facing and culling follow the sign of the polygon's area (Vulkan, Basic Polygon "
             "Rasterization and Culling; OpenGL 4.5 sections 14.6.1 and 14.6.2)";
    case Stage::DepthValue:
    case Stage::Quantisation:
      return "z is interpolated from the vertices' depths to about 1 part in 10^5 and converted "
             "to one of the two nearest 24-bit values (Vulkan, Depth Interpolation and "
             "Fixed-Point Data Conversions; OpenGL 4.5 sections 14.6.1, 2.3.4.1 and 2.3.5.2)";
    case Stage::DepthTest:
      return "the depth test compares the fragment's depth with the stored one by the depth "
             "function and writes it through the depth write mask (Vulkan, Depth Test; OpenGL "
             "4.5 section 17.3.6; WebGPU, depth test)";
    case Stage::Stencil:
      return "the stencil test compares (ref & mask) with (stencil & mask) and applies the op "
             "of its outcome through the write mask (Vulkan, Stencil Test; OpenGL 4.5 section "
             "17.3.5; WebGPU, stencil test)";
    case Stage::Clear:
      return "a clear writes only inside the scissor and through the write masks (OpenGL 4.5 "
             "sections 17.4.2 and 17.4.3; in Vulkan and WebGPU a draw that does what the "
             "contract's clear does)";
    case Stage::Validation:
      return "a native pipeline has no validation of its own: every vector of the kit is a "
             "valid stream";
  }
  return "";
}

Stage forbiddenStage(const ApiVerdict& v, Stage stage) {
  return v.stencilAllowed ? Stage::DepthValue : stage;
}

std::string describe(const ApiVerdict& v, const BadPixel& p, Stage stage) {
  if (v.allowed) {
    std::string out = "within the APIs' freedom: " + describe(v.freedoms);
    std::string how;
    std::size_t shown = 0;
    for (const OpenChoice& c : v.choices) {
      if ((v.freedoms & static_cast<FreedomSet>(c.freedom)) == 0 || shown == kChoicesShown)
        continue;
      how += (shown++ == 0 ? "" : "; ") + std::string("triangle ") + std::to_string(c.triangle) +
             " of draw " + std::to_string(c.draw) + ": " + c.how;
    }
    return how.empty() ? out : out + " (" + how + ")";
  }
  std::string out =
      "forbidden by the APIs: " + std::string(apiClause(forbiddenStage(v, stage))) + "; ";
  if (!v.stencilAllowed)
    out += "the back end's stencil " + std::to_string(static_cast<unsigned>(p.gotStencil)) +
           " is not among the allowed " + allowedStencils(v.states);
  else if (!v.depthAllowed)
    out += "the back end's depth " + std::to_string(p.gotDepth) + " is not among the allowed " +
           allowedDepths(v.states);
  else
    out += "the back end's depth " + std::to_string(p.gotDepth) + " and stencil " +
           std::to_string(static_cast<unsigned>(p.gotStencil)) +
           " are each allowed but not together (allowed: " + allowedDepths(v.states) + ")";
  return out;
}

}  // namespace recode::conformance
