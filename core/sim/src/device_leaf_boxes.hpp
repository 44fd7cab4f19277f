#pragma once
// The world boxes of a frame's leaves reduced on a device that keeps the blocks
// (raster::PosedBoxReducer), so that the host touches no vertex to make them: every stale leaf
// of the objects listed, in one submission, each box the bits posedVertexBox would give
// (a box the device flags, whose extreme is a zero or that met a NaN, is made again on the
// host). Private to core::Simulation.

#include <cstddef>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/raster/posed_boxes.hpp"
#include "recode/sim/hierarchy.hpp"

namespace recode::core::detail {

// Sets the box of every stale leaf of objects[i] for each i in `which` (ObjectTree::
// setLeafBox), reducing them on `device` (which is `reducer`) and running it once (finish()).
void reduceLeafBoxes(std::vector<ObjectTree>& objects, const std::vector<std::size_t>& which,
                     raster::DepthStencilDevice& device, raster::PosedBoxReducer& reducer);

// Puts every leaf's mesh on `device` now (the boxes of the current poses, thrown away), so that
// no frame pays for an upload, as the hierarchies are built before the first frame.
void keepLeafMeshes(const std::vector<ObjectTree>& objects, raster::DepthStencilDevice& device,
                    raster::PosedBoxReducer& reducer);

}  // namespace recode::core::detail
