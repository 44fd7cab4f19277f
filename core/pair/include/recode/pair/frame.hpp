#pragma once
// The frame a pair is rendered in: view axis, window and resolution. A scene may leave the
// window and resolution out; these functions supply the defaults of docs/scenes.md ("view") and
// turn "pixel size in world units" into a resolution (the paper's accuracy/time knob).

#include <array>
#include <optional>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/projection.hpp"
#include "recode/pair/view.hpp"

namespace recode::core {

// A concrete frame: what the device is sized to and the view maps onto.
struct FrameSpec {
  ViewAxis axis = ViewAxis::Z;  // the view direction: one of the world axes
  ViewWindow window;            // the world rectangle on the image plane the pixels cover
  int width = 800;              // pixels across the window
  int height = 800;             // pixel rows
};

// Command-line overrides of the scene's resolution ("--resolution W[xH]", "--pixel-size S").
// At most one of width and pixelSize may be set; height only with width.
struct FrameOverrides {
  std::optional<int> width;         // W of --resolution
  std::optional<int> height;        // H of --resolution WxH
  std::optional<double> pixelSize;  // S of --pixel-size, world units
};

// W and H of a frame when neither the scene nor an override gives a resolution.
inline constexpr int kDefaultResolution = 800;
// The default window is the objects' bounds on the image plane grown by this fraction of
// their larger in-plane extent on every side.
inline constexpr double kDefaultWindowMargin = 0.05;

// The frame for a view spec, the bounds of the objects and overrides:
// - pixel size (override, else the scene's): square pixels of that size over the window;
// - W x H (override, else the scene's resolution, else 800 x 800);
// - W alone: H follows the window's aspect, so pixels are square.
// Without a window in the spec the window is defaultWindow() for the chosen resolution.
// An override replaces the scene's resolution or pixel size, whichever it gave. Throws
// std::invalid_argument for an empty bounds box without a window, a resolution over 16384 or a
// pixel size larger than the window (checkPixelSizeFits).
[[nodiscard]] FrameSpec resolveFrame(const ViewSpec& spec, const Aabb& bounds,
                                     const FrameOverrides& overrides = {});

// The objects' bounds on the image plane of `axis`, grown by kDefaultWindowMargin. With a
// resolution, the shorter side is then widened about the centre so pixels are square.
[[nodiscard]] ViewWindow defaultWindow(ViewAxis axis, const Aabb& bounds,
                                       const std::optional<std::array<int, 2>>& resolution);

// W x H for a window and a pixel size: ceil(extent / pixelSize) per side, the window then
// widened about its centre to exactly W * pixelSize by H * pixelSize so pixels are square
// and of the requested size. Throws std::invalid_argument if the result exceeds 16384.
[[nodiscard]] FrameSpec frameFromPixelSize(ViewAxis axis, const ViewWindow& window,
                                           double pixelSize);

// Refuses a pixel size larger than the window's longer side: the frame would be one pixel
// around the whole window, widened about its centre to the pixel's size (1e308 gave a 1x1
// frame whose window lost every coordinate to rounding, and "no collision" for overlapping
// blocks). Throws std::invalid_argument stating the rule, e.g. "pixel size 1e+308 is larger
// than the window (2.1 by 2.1 world units): a frame needs at least one pixel within the window;
// give at most 2.1".
void checkPixelSizeFits(double pixelSize, const ViewWindow& window);

// H for W columns over the window with square pixels: rounded, clamped to 1..16384.
[[nodiscard]] int heightForWidth(const ViewWindow& window, int width);

}  // namespace recode::core
