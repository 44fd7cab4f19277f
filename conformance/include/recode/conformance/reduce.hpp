#pragma once
// Delta debugging of a failing vector: the smallest stream found that the back end still gets
// wrong at the same pixel, in the same buffers, at the same stage (diagnosis.hpp), with the
// expected buffers from the reference, ready to commit as a golden vector; and beside it a
// passing twin, one reduction step away from the minimal vector, that the back end gets right:
// the pair shows what the failure needs.
//
// The steps, repeated until none applies: drop commands (halves, then quarters, down to one at
// a time), drop triangles of a draw (likewise), drop vertices no index names, shrink the frame
// to the failing pixel's corner, move vertex coordinates to simpler values (whole pixels, pixel
// centres, fewer fraction bits) and depths to simpler floats (0, 1, 0.5, fewer mantissa bits).

#include <cstdint>
#include <optional>
#include <string>

#include "recode/conformance/backend.hpp"
#include "recode/conformance/diagnosis.hpp"
#include "recode/raster/golden.hpp"

namespace recode::conformance {

// How a vector fails: its first differing pixel (scan order), which buffers differ there, and
// the stage.
struct FailureSignature {
  int x = 0, y = 0;
  bool depth = false, stencil = false;
  bool refused = false;  // the back end refused the stream (then the rest is unused)
  Stage stage = Stage::Validation;
  friend bool operator==(const FailureSignature&, const FailureSignature&) = default;
};

// The signature of `got` against the reference's answer, or nothing when they are equal.
[[nodiscard]] std::optional<FailureSignature> signatureOf(const raster::CommandStream& stream,
                                                          const Answer& expected,
                                                          const Answer& got);

struct ReduceOptions {
  long long maxBackendRuns = 20000;  // the back end's answers the reduction may ask for
};

struct Reduction {
  FailureSignature signature;
  raster::GoldenVector minimal;                     // fails the same way; expected = reference
  std::optional<raster::GoldenVector> passingTwin;  // one step away; the back end passes it
  long long backendRuns = 0;
  int draws = 0, triangles = 0;  // in the minimal vector
};

// Throws std::invalid_argument when the back end does not fail `stream` to begin with.
[[nodiscard]] Reduction reduce(const raster::CommandStream& stream, Backend& backend,
                               const ReduceOptions& options = {});

}  // namespace recode::conformance
