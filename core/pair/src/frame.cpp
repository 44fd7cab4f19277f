#include "recode/pair/frame.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "recode/raster/state.hpp"

namespace recode::core {

namespace {

// The box's extent on the image plane of `axis` as (umin, vmin, umax, vmax).
ViewWindow planeBounds(ViewAxis axis, const Aabb& box) {
  const OrthoView probe(axis, {}, 1, 1, 0.0, 1.0);
  const Eigen::Vector3d lo = probe.toPlane(box.min), hi = probe.toPlane(box.max);
  return {lo.x(), lo.y(), hi.x(), hi.y()};
}

}  // namespace

ViewWindow defaultWindow(ViewAxis axis, const Aabb& bounds,
                         const std::optional<std::array<int, 2>>& resolution) {
  if (bounds.isEmpty())
    throw std::invalid_argument("cannot choose a view window for an empty scene");
  ViewWindow w = planeBounds(axis, bounds);
  double du = w.umax - w.umin, dv = w.vmax - w.vmin;
  // A block seen exactly edge-on still needs a window of some size.
  const double size = std::max({du, dv, 1e-9});
  const double margin = kDefaultWindowMargin * size;
  w.umin -= margin;
  w.umax += margin;
  w.vmin -= margin;
  w.vmax += margin;
  if (!resolution)
    return w;
  du = w.umax - w.umin;
  dv = w.vmax - w.vmin;
  const int cols = (*resolution)[0], rows = (*resolution)[1];
  // Square pixels: widen the side that is short for the pixel aspect.
  const double perPixel = std::max(du / cols, dv / rows);
  const double cu = 0.5 * (w.umin + w.umax), cv = 0.5 * (w.vmin + w.vmax);
  w.umin = cu - 0.5 * perPixel * cols;
  w.umax = cu + 0.5 * perPixel * cols;
  w.vmin = cv - 0.5 * perPixel * rows;
  w.vmax = cv + 0.5 * perPixel * rows;
  return w;
}

FrameSpec frameFromPixelSize(ViewAxis axis, const ViewWindow& window, double pixelSize) {
  if (!(pixelSize > 0.0) || !std::isfinite(pixelSize)) {
    std::ostringstream m;
    m << "pixel size " << pixelSize << " must be a positive finite number";
    throw std::invalid_argument(m.str());
  }
  const double du = window.umax - window.umin, dv = window.vmax - window.vmin;
  const double cols = std::ceil(du / pixelSize), rows = std::ceil(dv / pixelSize);
  const double limit = raster::kMaxFramebufferSize;
  if (!(cols <= limit) || !(rows <= limit)) {
    std::ostringstream m;
    m << "pixel size " << pixelSize << " gives " << cols << "x" << rows
      << " pixels for a window of " << du << " by " << dv << " world units; at most " << limit
      << " per side";
    throw std::invalid_argument(m.str());
  }
  FrameSpec f;
  f.axis = axis;
  f.width = std::max(1, static_cast<int>(cols));
  f.height = std::max(1, static_cast<int>(rows));
  const double cu = 0.5 * (window.umin + window.umax), cv = 0.5 * (window.vmin + window.vmax);
  f.window = {cu - 0.5 * pixelSize * f.width, cv - 0.5 * pixelSize * f.height,
              cu + 0.5 * pixelSize * f.width, cv + 0.5 * pixelSize * f.height};
  return f;
}

void checkPixelSizeFits(double pixelSize, const ViewWindow& window) {
  const double du = window.umax - window.umin, dv = window.vmax - window.vmin;
  const double longer = std::max(du, dv);
  if (pixelSize > longer) {
    std::ostringstream m;
    m << "pixel size " << pixelSize << " is larger than the window (" << du << " by " << dv
      << " world units): a frame needs at least one pixel within the window; give at most "
      << longer;
    throw std::invalid_argument(m.str());
  }
}

int heightForWidth(const ViewWindow& window, int width) {
  const double rows = std::round(width * (window.vmax - window.vmin) / (window.umax - window.umin));
  return static_cast<int>(std::clamp(rows, 1.0, static_cast<double>(raster::kMaxFramebufferSize)));
}

FrameSpec resolveFrame(const ViewSpec& spec, const Aabb& bounds, const FrameOverrides& overrides) {
  if (overrides.width && overrides.pixelSize)
    throw std::invalid_argument("give a resolution or a pixel size, not both");
  if (overrides.height && !overrides.width)
    throw std::invalid_argument("a height override needs a width");
  const auto checkSide = [](int n, const char* what) {
    if (n < 1 || n > raster::kMaxFramebufferSize) {
      std::ostringstream m;
      m << what << " " << n << " is outside 1.." << raster::kMaxFramebufferSize;
      throw std::invalid_argument(m.str());
    }
  };
  // The window the resolution is chosen for (value_or would build the default eagerly).
  const auto windowFor = [&](const std::optional<std::array<int, 2>>& res) {
    return spec.window ? *spec.window : defaultWindow(spec.axis, bounds, res);
  };
  std::optional<double> pixelSize = overrides.pixelSize;
  std::optional<std::array<int, 2>> resolution;
  bool widthOnly = false;
  if (overrides.width) {
    checkSide(*overrides.width, "width");
    if (overrides.height) {
      checkSide(*overrides.height, "height");
      resolution = std::array<int, 2>{*overrides.width, *overrides.height};
    } else {
      widthOnly = true;
    }
  } else if (!pixelSize) {
    pixelSize = spec.pixelSize;
    if (!pixelSize)
      resolution =
          spec.resolution.value_or(std::array<int, 2>{kDefaultResolution, kDefaultResolution});
  }
  if (pixelSize) {
    const ViewWindow window = windowFor(std::nullopt);
    checkPixelSizeFits(*pixelSize, window);
    return frameFromPixelSize(spec.axis, window, *pixelSize);
  }
  FrameSpec f;
  f.axis = spec.axis;
  if (widthOnly) {
    const int width = *overrides.width;
    const int height = heightForWidth(windowFor(std::nullopt), width);
    resolution = std::array<int, 2>{width, height};
  }
  f.width = (*resolution)[0];
  f.height = (*resolution)[1];
  checkSide(f.width, "width");
  checkSide(f.height, "height");
  f.window = windowFor(resolution);
  return f;
}

}  // namespace recode::core
