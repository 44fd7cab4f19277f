#pragma once
// An optional capability of a device that keeps blocks for posed draws (TriangleSource::
// posedMesh): the world boxes of blocks at poses, reduced where the blocks are, so that a
// frame's host never touches their vertices (docs/architecture.md, "Posed draws"). A device
// that has it derives from PosedBoxReducer as well as from DepthStencilDevice; a caller finds
// it with dynamic_cast.

#include <array>
#include <span>

#include "recode/raster/pending_read.hpp"
#include "recode/raster/triangle_source.hpp"

namespace recode::raster {

// A block's world box: per world axis the smallest and the largest coordinate of
// poseVertex(pose, v) over its vertices (+inf and -inf for a block without vertices).
struct PosedBox {
  std::array<double, 3> min{};
  std::array<double, 3> max{};
  // Whether the order of the comparisons could decide the bits: an extreme that is a zero (+0
  // and -0 compare equal, so which one a reduction keeps depends on its order) or a NaN among
  // the coordinates. Such a box must be made again in the caller's own order; every other box
  // is the same bits in any order.
  bool orderMatters = false;
};

class PosedBoxReducer {
 public:
  virtual ~PosedBoxReducer() = default;

  // The box of each mesh at its transform's pose (the window mapping is not used), in order,
  // delivered by the device's finish(). The meshes are kept as posed draws keep them (their
  // meshKey and alive), so a block whose box was reduced is drawn without another upload.
  [[nodiscard]] virtual PendingRead<PosedBox> posedBoxesLater(
      std::span<const PosedMesh> meshes) = 0;
};

}  // namespace recode::raster
