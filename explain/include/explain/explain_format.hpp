#pragma once
// Small text pieces for the explain page: HTML escaping, numbers, rectangles, points, swatches.

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "explain/png_image.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/state.hpp"

namespace recode::explain {

[[nodiscard]] std::string escapeHtml(std::string_view text);
// Six significant digits.
[[nodiscard]] std::string formatNumber(double v);
// "[x0, y0, x1, y1)".
[[nodiscard]] std::string rectText(const raster::PixelRect& r);
// "(x, y, z)".
[[nodiscard]] std::string pointText(const Eigen::Vector3d& p);
// An HTML colour swatch for legends and tables.
[[nodiscard]] std::string swatch(Rgb c);

}  // namespace recode::explain
