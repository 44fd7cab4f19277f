#pragma once
// The frame a pair is rendered in: view axis, window and resolution. A scene may leave the
// window and resolution out; these functions supply the defaults of DESIGN.md section 6 and
// turn "pixel size in world units" into a resolution (the paper's accuracy/time knob).

#include <array>
#include <optional>

#include "recode/core/mesh.hpp"
#include "recode/core/view.hpp"

namespace recode::core {

struct FrameSpec {
  ViewAxis axis = ViewAxis::Z;
  ViewWindow window;
  int width = 800;
  int height = 800;
};

inline constexpr int kDefaultResolution = 800;
// The default window is the objects' bounds on the image plane grown by this fraction of
// their larger in-plane extent on every side.
inline constexpr double kDefaultWindowMargin = 0.05;

// The objects' bounds on the image plane of `axis`, grown by kDefaultWindowMargin, and made
// square-pixelled for the given resolution aspect when `resolution` is set (the shorter side
// of the window is widened about its centre).
[[nodiscard]] ViewWindow defaultWindow(ViewAxis axis, const Aabb& bounds,
                                       const std::optional<std::array<int, 2>>& resolution);

// W x H for a window and a pixel size: ceil(extent / pixelSize) per side, the window then
// widened about its centre to exactly W * pixelSize by H * pixelSize so pixels are square
// and of the requested size. Throws std::invalid_argument if the result exceeds 16384.
[[nodiscard]] FrameSpec frameFromPixelSize(ViewAxis axis, const ViewWindow& window,
                                           double pixelSize);

// H for "--resolution W" (no H): the window's aspect at W columns, rounded, at least 1.
[[nodiscard]] int heightForWidth(const ViewWindow& window, int width);

}  // namespace recode::core
