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
  r.depth.latitudes = namesOf(depth);
  r.stencil.latitudes = namesOf(stencil);
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
  return infoOf(stage).apiClause;
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
