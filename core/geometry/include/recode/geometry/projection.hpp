#pragma once
// What an orthographic view is asked to be, before any frame is chosen: the world axis it looks
// along, and optionally the window on its image plane and the resolution or pixel size. Scene
// files describe it (the "view" object, docs/scenes.md); the pair layer resolves it into a
// concrete frame (recode/pair/frame.hpp) and maps world points onto pixels (recode/pair/view.hpp).
// It lives here, below both, so that scenes can be read without the pair algorithm.

#include <array>
#include <optional>
#include <string_view>

namespace recode::core {

// The view axis and its image plane (right-handed, no mirror): z -> (x, y), x -> (y, z),
// y -> (z, x).
enum class ViewAxis { X, Y, Z };

// "x", "y", "z" as in scene files and output; parseViewAxis returns nullopt for anything else.
[[nodiscard]] std::string_view toString(ViewAxis axis);
[[nodiscard]] std::optional<ViewAxis> parseViewAxis(std::string_view name);

// [umin, vmin, umax, vmax] in world units on the image plane.
struct ViewWindow {
  double umin = -1.0;
  double vmin = -1.0;
  double umax = 1.0;
  double vmax = 1.0;
};

// The "view" object of a scene file. Window and resolution are optional; resolveFrame()
// fills in the defaults.
struct ViewSpec {
  ViewAxis axis = ViewAxis::Z;
  std::optional<ViewWindow> window;              // "window": [umin, vmin, umax, vmax]
  std::optional<std::array<int, 2>> resolution;  // "resolution": [W, H]
  std::optional<double> pixelSize;               // "pixel_size": world units per pixel
};

}  // namespace recode::core
