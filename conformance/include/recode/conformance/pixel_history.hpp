#pragma once
// One pixel's history under the contract (docs/rasterization.md): every clear and every
// triangle that reached the pixel, with the arithmetic that decided what it did, in the
// contract's own terms and order. It is computed from the stream alone, independently of any
// device, the way a conformance report explains a bad pixel: what the reference did there, step
// by step, beside what the back end left.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "recode/raster/command_stream.hpp"

namespace recode::conformance {

// The quantisation of z (section 5).
struct Quantisation {
  double scaled = 0;         // z * 16777215.0 as a double (when 0 < z < 1)
  bool clampedLow = false;   // z <= 0 or NaN: q = 0
  bool clampedHigh = false;  // z >= 1: q = 16777215
  bool tie = false;          // scaled is exactly k + 0.5: rounded to whichever of k, k + 1 is even
  std::uint32_t q = 0;
};

// A clear that covered the pixel (inside the scissor). Before and after are set for both
// buffers (the one a clear does not write keeps its value), so events chain.
struct ClearEvent {
  bool depth = false;            // clear_depth, else clear_stencil
  double value = 0.0;            // as given (depth in [0, 1], or the stencil byte)
  bool skipped = false;          // clear_depth while the depth write mask is off: nothing written
  std::uint8_t writeMask = 255;  // clear_stencil: the stencil write mask applied
  Quantisation quantisation;     // clear_depth: the quantisation of value (also when skipped)
  bool outsideScissor = false;   // the scissor excludes the pixel: the clear leaves it as it is
  std::uint32_t depthBefore = 0, depthAfter = 0;
  std::uint8_t stencilBefore = 0, stencilAfter = 0;
};

// One edge of the triangle in counter-clockwise order (section 4) at the pixel's sample.
struct EdgeAtSample {
  int from = 0, to = 0;      // submitted vertex indices 0..2 of the edge a -> b
  long long dx = 0, dy = 0;  // Xb - Xa, Yb - Ya
  long long value = 0;       // E(Xc, Yc) = dx (Yc - Ya) - dy (Xc - Xa)
  bool inclusive = false;    // dy < 0 or (dy == 0 and dx > 0)
  [[nodiscard]] bool passes() const { return value > 0 || (value == 0 && inclusive); }
};

// The depth plane's terms (section 5) in the contract's order, at the pixel's sample.
struct PlaneTerms {
  double z0 = 0, dz1 = 0, dz2 = 0;
  double e1x = 0, e1y = 0, e2x = 0, e2y = 0, a2 = 0;
  double dzdxNumerator = 0, dzdyNumerator = 0;  // dz1 e2y - dz2 e1y,  dz2 e1x - dz1 e2x
  double dzdx = 0, dzdy = 0;
  double sampleDx = 0, sampleDy = 0;  // Xc - X0, Yc - Y0
  double tx = 0, ty = 0;
  double z0PlusTx = 0;
  double z = 0;  // (z0 + tx) + ty: before quantisation
};

// Why a triangle that reached the pixel drew no fragment there, or did. A triangle reaches the
// pixel when every edge value at the sample is >= 0 (it covers the sample, or would but for
// the tie rule). The outcome is the first of these, in the pipeline's order, that stops it:
// culling (section 3), the scissor, the fill rule's tie (section 4); else it is a fragment.
enum class TriangleOutcome {
  Fragment,        // covered: a fragment ran the per-fragment operations
  Degenerate,      // A2 = 0 after snapping (never recorded: such a triangle has no edges)
  Culled,          // culled by its facing
  OutsideScissor,  // not culled, but the scissor excludes the pixel
  ExcludedByTie,   // every edge value >= 0 but one that is exactly 0 is not inclusive
};

struct TriangleEvent {
  int draw = 0;      // index of the draw among the stream's draws (0-based)
  int triangle = 0;  // triangle index within the draw (indices 3t, 3t+1, 3t+2)
  int command = 0;   // index of the draw command in the stream
  TriangleOutcome outcome = TriangleOutcome::Fragment;
  long long X[3] = {0, 0, 0}, Y[3] = {0, 0, 0};  // snapped, submitted order
  float Z[3] = {0, 0, 0};
  long long area2 = 0;  // A2
  bool front = true;
  EdgeAtSample edges[3];      // counter-clockwise order
  raster::PixelRect scissor;  // the scissor in force (clamped to the frame)
  // Before and after are set for every outcome (equal unless a fragment changed them), so
  // that events chain; the rest is set for outcome Fragment only, but for the plane and the
  // quantisation, which ExcludedByTie also has (the depth the fragment would have had).
  std::uint32_t depthBefore = 0, depthAfter = 0;
  std::uint8_t stencilBefore = 0, stencilAfter = 0;
  PlaneTerms plane;
  Quantisation quantisation;
  // Per-fragment operations (section 6).
  std::uint8_t stencilRef = 0, valueMask = 255, writeMask = 255;
  std::string stencilFunc, depthFunc;               // GL names, e.g. "LESS"
  bool stencilPassed = false, depthPassed = false;  // depthPassed meaningful when stencilPassed
  std::string op;          // the op taken: sfail, dpfail or dppass's value, e.g. "INCR"
  std::string opSlot;      // "sfail", "dpfail" or "dppass"
  bool depthWrite = true;  // the depth write mask
};

struct HistoryEvent {
  int command = 0;  // index in the stream
  std::optional<ClearEvent> clear;
  std::optional<TriangleEvent> triangle;
};

struct PixelHistory {
  int x = 0, y = 0;
  std::vector<HistoryEvent> events;  // in stream order
  std::uint32_t finalDepth = 16777215;
  std::uint8_t finalStencil = 0;
};

// The history of pixel (x, y) (GL window coordinates, y = 0 the bottom row) under `stream`.
// Records every clear (one the scissor keeps from the pixel marked outsideScissor: a back end
// that ignores the scissor shows there) and every triangle with outcome Fragment, and the triangles
// that would cover the sample but for culling, the scissor or the tie rule (not degenerate ones
// or those that miss the sample). Throws std::invalid_argument for a pixel outside the frame,
// a frame size outside 1..16384, and (as the device does, section 2) a draw that fails
// validation or a non-finite depth clear, naming the command.
[[nodiscard]] PixelHistory pixelHistory(const raster::CommandStream& stream, int x, int y);

// The history as text, one line per event and indented lines for the arithmetic, for reports.
[[nodiscard]] std::string describe(const PixelHistory& history);

}  // namespace recode::conformance
