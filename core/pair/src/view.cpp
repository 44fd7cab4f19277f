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

raster::WindowMapping OrthoView::windowMapping() const {
  raster::WindowMapping m;
  switch (axis_) {  // toPlane's order
    case ViewAxis::X:
      m.axes = {1, 2, 0};
      break;
    case ViewAxis::Y:
      m.axes = {2, 0, 1};
      break;
    case ViewAxis::Z:
      m.axes = {0, 1, 2};
      break;
  }
  m.umin = window_.umin;
  m.urange = window_.umax - window_.umin;
  m.width = width_;
  m.vmin = window_.vmin;
  m.vrange = window_.vmax - window_.vmin;
  m.height = height_;
  m.depthMax = depthMax_;
  m.depthRange = depthMax_ - depthMin_;
  return m;
}

raster::WindowVertex OrthoView::toWindow(const Eigen::Vector3d& world) const {
  return toWindow(windowMapping(), world);
}

raster::WindowVertex OrthoView::toWindow(const raster::WindowMapping& mapping,
                                         const Eigen::Vector3d& world) const {
  const raster::WindowPosition p = raster::mapToWindow(mapping, {world.x(), world.y(), world.z()});
  if (raster::drawablePosition(p))
    return raster::snapPosition(p);
  const double limit = static_cast<double>(raster::kMaxWindowCoordinate);
  if (!(std::fabs(p.x) <= limit) || !(std::fabs(p.y) <= limit)) {
    std::ostringstream m;
    m << "point (" << world.x() << ", " << world.y() << ", " << world.z()
      << ") maps to window position (" << p.x << ", " << p.y
      << ") beyond the +-32768 pixel range of 24.8 fixed point";
    throw std::invalid_argument(m.str());
  }
  std::ostringstream m;
  m << "point (" << world.x() << ", " << world.y() << ", " << world.z()
    << ") lies outside the view's depth range [" << depthMin_ << ", " << depthMax_ << "]";
  throw std::invalid_argument(m.str());
}

std::vector<raster::WindowVertex> OrthoView::toWindow(const TriangleMesh& mesh) const {
  std::vector<raster::WindowVertex> out;
  out.reserve(mesh.vertices.size());
  const raster::WindowMapping mapping = windowMapping();
  for (const Eigen::Vector3d& p : mesh.vertices)
    out.push_back(toWindow(mapping, p));
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
