#pragma once
// The conformance kit's vertex-stage vectors (docs/rasterization.md, sections 2.1 and 9): block
// vertices with the pose and window mapping of one draw, and the window vertices the contract's
// vertex stage (raster/vertex_stage.hpp) makes of them, bit for bit. A device that runs the
// stage itself (a posed draw) must reproduce every expected vertex.
//
// Beside them, the plausible wrong readings of section 2.1 (another order of the sums, a fused
// multiply-add, single precision, another rounding), each as a function computing the window
// vertex; tests/raster/vertex_stage_vectors_test.cpp proves that every reading gets at least
// kMinVertexStageCatches vectors wrong. The vectors are deterministic (fixed seeds, ranges made
// from std::mt19937_64's raw bits): the same on every run and platform, and
// data/golden/vertex-stage.jsonl is what vertexStageGoldenText writes of them.

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "recode/raster/vertex_stage.hpp"
#include "recode/raster/window_vertex.hpp"

namespace recode::kit {

struct VertexStageVector {
  std::string name;  // <group>_<view axis>[_<index>], e.g. "rotated_x_1"
  raster::VertexTransform transform;
  std::vector<std::array<double, 3>> local;    // the block's own coordinates
  std::vector<raster::WindowVertex> expected;  // raster::vertexStage of each local vertex
};

// The vectors, in a fixed order: rotated and translated blocks seen along Z, X and Y, blocks far
// from the origin, and the special cases (snap ties, signed zeros, depths halfway between two
// floats, depths below the smallest normal float). Every expected vertex is a drawable position
// (raster::drawablePosition); the generator throws std::logic_error if one is not.
[[nodiscard]] std::vector<VertexStageVector> vertexStageVectors();

// The wrong readings of the stage. Each changes one step: the pose, the window mapping, the
// snapping of x and y, or the rounding of z to float.
enum class VertexStageReading {
  Contract,  // raster::vertexStage
  // The pose.
  ZRowAsXY,          // the z row summed as the x and y rows: ((l20 px + l21 py) + l22 pz) + tz
  RowsRightFirst,    // every row summed as l0 p0 + (l1 p1 + l2 p2), then + t
  TranslationFirst,  // every row as ((t + l0 p0) + l1 p1) + l2 p2
  FmaPose,           // the rows' products fused with std::fma, in the contract's order
  FloatPose,         // the pose in single precision
  LinearTransposed,  // `linear` read column by column (Eigen's storage order)
  // The window mapping.
  FloatWindow,          // the mapping in single precision
  WindowScaleFirst,     // x = (w[u] - umin) * (width / urange), y alike
  WindowMultiplyFirst,  // x = (w[u] - umin) * width / urange, y alike
  DepthReciprocal,      // z = (depthMax - w[d]) * (1 / depthRange)
  DepthFromMin,         // z = 1 - (w[d] - depthMin) / depthRange, depthMin = depthMax - depthRange
  DepthReversed,        // z = (w[d] - depthMin) / depthRange: depthMin taken as the near end
  AxesInverted,         // w[u] taken as the world coordinate whose index is u's position in axes
  YDown,                // y = (vmax - w[v]) / vrange * height: rows counted from the top
  // Snapping x and y to the 1/256-pixel grid.
  SnapAfterFloat,      // x and y rounded to float first, then snapped
  SnapHalfAway,        // std::round(x 256) / 256: ties away from zero
  SnapHalfUp,          // floor(x 256 + 0.5) / 256: ties up
  SnapThroughInteger,  // float(llrint(x 256)) / 256: a snapped -0 becomes +0
  // Rounding z to float.
  DepthTruncate,        // toward zero
  DepthTiesAway,        // to nearest, ties away from zero
  DepthFlushSubnormal,  // to nearest, a subnormal float flushed to +0 (a GPU's FTZ)
};

struct VertexStageReadingInfo {
  VertexStageReading reading;
  std::string_view name;  // e.g. "z_row_as_xy"
  std::string_view what;  // one line
};

// Every wrong reading (not Contract), in the order above.
[[nodiscard]] std::span<const VertexStageReadingInfo> wrongVertexStageReadings();
[[nodiscard]] std::string_view vertexStageReadingName(VertexStageReading reading);

// The window vertex the reading makes of `local`.
[[nodiscard]] raster::WindowVertex vertexStageAs(VertexStageReading reading,
                                                 const raster::VertexTransform& transform,
                                                 const std::array<double, 3>& local);

// Whether x, y and z have the same bits (so -0 and +0 differ).
[[nodiscard]] bool sameBits(const raster::WindowVertex& a, const raster::WindowVertex& b);

// The promise: every wrong reading gets at least this many vectors wrong.
inline constexpr int kMinVertexStageCatches = 3;

// The vectors as the golden file data/golden/vertex-stage.jsonl (format recode-vertex-stage-1,
// docs/rasterization.md section 9): a header line, then one JSON object per vector and line;
// doubles as hexadecimal floating-point strings (Python's float.hex()), each expected float as a
// decimal and as its 32-bit pattern. Ends with a newline.
[[nodiscard]] std::string vertexStageGoldenText(const std::vector<VertexStageVector>& vectors);

// The canonical hexadecimal form of a double, as Python's float.hex() writes it:
// "0x1.8000000000000p+1", "-0x0.0p+0", "0x0.0000000000001p-1022". Finite values only.
[[nodiscard]] std::string hexDouble(double value);

}  // namespace recode::kit
