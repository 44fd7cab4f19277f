#pragma once
// World -> window mapping (docs/algorithm.md section 2): an orthographic view along a world axis,
// GL conventions (the viewer on the + side of the axis looking toward -, so depth grows as
// the coordinate along the axis decreases), the scene window onto W x H pixels, window x and
// y pre-snapped to the 1/256-pixel grid so every back end starts from the same vertices.

#include <Eigen/Core>
#include <optional>
#include <string_view>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/projection.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/vertex_stage.hpp"

namespace recode::core {

class OrthoView {
 public:
  // depthMin/depthMax: the world extent along the axis that maps onto depth [1, 0] (the far
  // end, smallest coordinate, is depth 1). Throws std::invalid_argument for a degenerate or
  // non-finite window or depth range, or a resolution outside 1..16384.
  OrthoView(ViewAxis axis, const ViewWindow& window, int width, int height, double depthMin,
            double depthMax);

  [[nodiscard]] ViewAxis axis() const { return axis_; }
  [[nodiscard]] const ViewWindow& window() const { return window_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double depthMin() const { return depthMin_; }
  [[nodiscard]] double depthMax() const { return depthMax_; }

  // (u, v, d): the image-plane coordinates and the coordinate along the axis.
  [[nodiscard]] Eigen::Vector3d toPlane(const Eigen::Vector3d& world) const;
  // Inline: the contact measurement calls it twice per pixel, and an out-of-line call loads
  // the point it was just given through memory, which costs a failed store forwarding.
  [[nodiscard]] Eigen::Vector3d fromPlane(const Eigen::Vector3d& q) const {
    switch (axis_) {
      case ViewAxis::X:
        return {q.z(), q.x(), q.y()};
      case ViewAxis::Y:
        return {q.y(), q.z(), q.x()};
      case ViewAxis::Z:
        break;
    }
    return {q.x(), q.y(), q.z()};
  }

  // The view as the contract's vertex stage maps world to window (raster::WindowMapping,
  // docs/rasterization.md section 2.1): toWindow's arithmetic.
  [[nodiscard]] raster::WindowMapping windowMapping() const;

  // World point -> window vertex by the vertex stage (raster::mapToWindow, then
  // raster::snapPosition): x and y snapped to 1/256 pixel, z in [0, 1]. Throws
  // std::invalid_argument for a point beyond the device's coordinate range or outside the
  // depth range.
  [[nodiscard]] raster::WindowVertex toWindow(const Eigen::Vector3d& world) const;
  // The same with windowMapping() made once by the caller.
  [[nodiscard]] raster::WindowVertex toWindow(const raster::WindowMapping& mapping,
                                              const Eigen::Vector3d& world) const;
  [[nodiscard]] std::vector<raster::WindowVertex> toWindow(const TriangleMesh& mesh) const;

  // Window position (pixels) and normalised depth -> world point: fromPlane of the three below.
  [[nodiscard]] Eigen::Vector3d toWorld(double windowX, double windowY, double depth) const;
  // toWorld's image-plane u of a window x, v of a window y, and d of a normalised depth, each
  // alone, for callers that share one across many points (a row's v, a pixel's u).
  [[nodiscard]] double planeU(double windowX) const {
    return window_.umin + windowX / width_ * (window_.umax - window_.umin);
  }
  [[nodiscard]] double planeV(double windowY) const {
    return window_.vmin + windowY / height_ * (window_.vmax - window_.vmin);
  }
  [[nodiscard]] double planeD(double depth) const {
    return depthMax_ - depth * (depthMax_ - depthMin_);
  }

  // World size of one pixel along u and v.
  [[nodiscard]] double pixelWidth() const { return (window_.umax - window_.umin) / width_; }
  [[nodiscard]] double pixelHeight() const { return (window_.vmax - window_.vmin) / height_; }

 private:
  ViewAxis axis_;
  ViewWindow window_;
  int width_;
  int height_;
  double depthMin_;
  double depthMax_;
};

// Flattens a mesh's triangles into a device index list.
[[nodiscard]] std::vector<std::uint32_t> triangleIndices(const TriangleMesh& mesh);

}  // namespace recode::core
