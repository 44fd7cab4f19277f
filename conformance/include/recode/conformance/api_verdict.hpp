#pragma once
// A bad pixel judged against what the graphics APIs allow (api_freedoms.hpp): either the back
// end's values are among the states the APIs' freedoms allow there (a departure from this
// contract within the APIs' freedom: which freedoms, and how far), or they are not (a departure
// the APIs forbid, with the clause that fixes the stage it departs at). Only the second is a
// bug of a native pipeline.

#include <string>
#include <string_view>
#include <vector>

#include "recode/conformance/api_freedoms.hpp"
#include "recode/conformance/diagnosis.hpp"

namespace recode::conformance {

// A bad pixel against the APIs.
struct ApiVerdict {
  bool allowed = false;              // the back end's depth and stencil are one allowed state
  bool depthAllowed = false;         // its depth is in some allowed state
  bool stencilAllowed = false;       // its stencil is in some allowed state
  FreedomSet freedoms = 0;           // allowed: the freedoms on the paths to the back end's state
  std::vector<OpenChoice> choices;   // what the freedoms opened at the pixel, in stream order
  std::vector<AllowedState> states;  // every allowed state of the pixel
};

// Whether the APIs fix each buffer of a vector (every pixel exactly one value), and the
// freedoms that leave some pixel of it open.
[[nodiscard]] Requirement requirementOf(const AllowedFrame& frame);

// A failing answer's bad pixels counted against the APIs.
struct ApiTally {
  long long forbidden = 0;      // pixels whose values no allowed state holds
  long long withinFreedom = 0;  // pixels whose values an allowed state holds
  FreedomSet freedoms = 0;      // the freedoms on the paths to the latter
};
// Counts `bad` against `frame`.
[[nodiscard]] ApiTally tallyByApis(const AllowedFrame& frame, const std::vector<BadPixel>& bad);

// Judges a bad pixel of `stream`.
[[nodiscard]] ApiVerdict judgeByApis(const raster::CommandStream& stream, const BadPixel& pixel,
                                     const FreedomWidths& widths = {});

// The clauses of the APIs that fix a stage's rule (coverage and facing: the sample's side of
// every allowed edge; stencil: the stencil test and ops; ...), in one line.
[[nodiscard]] std::string_view apiClause(Stage stage);

// The stage whose clause a forbidden pixel breaks: `stage` (the diagnosis's) when the back
// end's stencil is not allowed, else the depth value's (coverage and the stencil may be allowed
// while the depth that goes with them is not).
[[nodiscard]] Stage forbiddenStage(const ApiVerdict& verdict, Stage stage);

// The verdict in one paragraph for reports: "within the APIs' freedom: the sub-pixel precision
// (the sample lies 7.6e-06 pixels from edge v0 -> v1, ...)" or "forbidden by the APIs (<clause>):
// the back end's stencil 3 is not among the allowed 1, 2".
[[nodiscard]] std::string describe(const ApiVerdict& verdict, const BadPixel& pixel, Stage stage);

}  // namespace recode::conformance
