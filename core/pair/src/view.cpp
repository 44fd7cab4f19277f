#include "recode/pair/view.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "recode/raster/fixed_point.hpp"

namespace recode::core {

OrthoView::OrthoView(ViewAxis axis, const ViewWindow& window, int width, int height,
                     double depthMin, double depthMax)
    : axis_(axis),
      window_(window),
      width_(width),
      height_(height),
      depthMin_(depthMin),
      depthMax_(depthMax) {
  if (width < 1 || height < 1 || width > raster::kMaxFramebufferSize ||
      height > raster::kMaxFramebufferSize) {
    std::ostringstream m;
    m << "resolution " << width << "x" << height << " is outside 1.." << raster::kMaxFramebufferSize
      << " in each dimension";
    throw std::invalid_argument(m.str());
  }
  const bool finite = std::isfinite(window.umin) && std::isfinite(window.vmin) &&
                      std::isfinite(window.umax) && std::isfinite(window.vmax) &&
                      std::isfinite(depthMin) && std::isfinite(depthMax);
  if (!finite || !(window.umax > window.umin) || !(window.vmax > window.vmin)) {
    std::ostringstream m;
    m << "view window [" << window.umin << ", " << window.vmin << ", " << window.umax << ", "
      << window.vmax << "] must be finite with umin < umax and vmin < vmax";
    throw std::invalid_argument(m.str());
  }
  if (!finite || !(depthMax > depthMin)) {
    std::ostringstream m;
    m << "depth range [" << depthMin << ", " << depthMax << "] must be finite and non-empty";
    throw std::invalid_argument(m.str());
  }
}

Eigen::Vector3d OrthoView::toPlane(const Eigen::Vector3d& p) const {
  switch (axis_) {
    case ViewAxis::X:
      return {p.y(), p.z(), p.x()};
    case ViewAxis::Y:
      return {p.z(), p.x(), p.y()};
    case ViewAxis::Z:
      break;
  }
  return {p.x(), p.y(), p.z()};
}

raster::WindowVertex OrthoView::toWindow(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d q = toPlane(world);
  const double x = (q.x() - window_.umin) / (window_.umax - window_.umin) * width_;
  const double y = (q.y() - window_.vmin) / (window_.vmax - window_.vmin) * height_;
  const double z = (depthMax_ - q.z()) / (depthMax_ - depthMin_);
  const double limit = static_cast<double>(raster::kMaxWindowCoordinate);
  if (!(std::fabs(x) <= limit) || !(std::fabs(y) <= limit)) {
    std::ostringstream m;
    m << "point (" << world.x() << ", " << world.y() << ", " << world.z()
      << ") maps to window position (" << x << ", " << y
      << ") beyond the +-32768 pixel range of 24.8 fixed point";
    throw std::invalid_argument(m.str());
  }
  if (!(z >= 0.0 && z <= 1.0)) {
    std::ostringstream m;
    m << "point (" << world.x() << ", " << world.y() << ", " << world.z()
      << ") lies outside the view's depth range [" << depthMin_ << ", " << depthMax_ << "]";
    throw std::invalid_argument(m.str());
  }
  return {raster::snapToSubpixel(x), raster::snapToSubpixel(y), static_cast<float>(z)};
}

std::vector<raster::WindowVertex> OrthoView::toWindow(const TriangleMesh& mesh) const {
  std::vector<raster::WindowVertex> out;
  out.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p : mesh.vertices)
    out.push_back(toWindow(p));
  return out;
}

Eigen::Vector3d OrthoView::toWorld(double windowX, double windowY, double depth) const {
  return fromPlane({planeU(windowX), planeV(windowY), planeD(depth)});
}

std::vector<std::uint32_t> triangleIndices(const TriangleMesh& mesh) {
  std::vector<std::uint32_t> out;
  out.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    out.insert(out.end(), t.begin(), t.end());
  return out;
}

}  // namespace recode::core
