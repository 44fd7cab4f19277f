#pragma once
// Delta debugging of a failing vector: the smallest stream found that the back end still gets
// wrong at the same pixel, in the same buffers, at the same stage (diagnosis.hpp), with the
// expected buffers from the reference, ready to commit as a golden vector; and beside it a
// passing twin, one reduction step away from the minimal vector, that the back end gets right:
// the pair shows what the failure needs.
//
// The steps, in this order, repeated until a whole round takes none: shrink the frame to end at
// the failing pixel (it is the first in scan order, so it stays first; a refused stream goes to
// 1 x 1), drop commands (halves, then quarters, down to one at a time), drop triangles of a
// draw (likewise; a draw that loses its last one goes), drop vertices no index names, move
// state commands' fields to GL's defaults (a clear's value to 1, 0 or 0.5), move vertex
// coordinates to simpler values (the nearest whole pixels, the nearest pixel centre, fewer
// fraction bits) and depths to simpler floats (0, 1, 0.5, fewer mantissa bits). A step is taken
// when the candidate fails the same way; every step makes the stream smaller or its values
// simpler, never back, so the rounds end. Every candidate is a valid stream (section 2 of
// docs/rasterization.md: coordinates stay on the 1/256 grid within +-32768, depths floats in
// [0, 1]), so the minimal vector and its twin read back from their files unchanged.
//
// Deterministic: a back end that answers the same stream the same way gets the same reduction.

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

// The signature of `got` against the reference's answer, or nothing when they are equal. The
// stage is failingStage's without the wrong readings' answers (from the reference's history of
// the pixel alone), which is cheap enough to ask of every candidate. A refusal is {refused,
// Validation}. Throws std::invalid_argument when an answer's buffers are not width x height.
[[nodiscard]] std::optional<FailureSignature> signatureOf(const raster::CommandStream& stream,
                                                          const Answer& expected,
                                                          const Answer& got);

struct ReduceOptions {
  // The back end's answers the reduction may ask for, the first (the input's) included; once
  // spent, the smallest stream found so far is the result (it still fails the same way).
  long long maxBackendRuns = 20000;
};

struct Reduction {
  FailureSignature signature;  // the input's, and the minimal vector's
  // Fails the same way; expected buffers from the reference (referenceAnswer). Its description
  // says it was reduced, from what, the back end's name, the runs and the signature.
  raster::GoldenVector minimal;
  // Of the candidates tried on the minimal vector itself (the last round, which took no step),
  // one the back end passes (its answer equals the reference's): the smallest step, counted in
  // elements moved or removed (one coordinate, depth or state field; one triangle; one
  // command), and of equal size a moved value before a removed part, since it shows more
  // sharply what the failure needs. Empty when every step tried from the minimal vector still
  // fails (the same or another way), or the budget ran out before one passed.
  std::optional<raster::GoldenVector> passingTwin;
  long long backendRuns = 0;
  int draws = 0, triangles = 0;  // in the minimal vector
};

// Throws std::invalid_argument when the back end does not fail `stream` to begin with, or the
// stream is not valid under the contract; a BackendError from the back end propagates.
[[nodiscard]] Reduction reduce(const raster::CommandStream& stream, Backend& backend,
                               const ReduceOptions& options = {});

}  // namespace recode::conformance
