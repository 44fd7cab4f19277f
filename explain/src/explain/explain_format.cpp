// Small text pieces for the explain page: HTML escaping, numbers, rectangles, points, swatches.
#include "explain/explain_format.hpp"

#include <iomanip>
#include <sstream>

namespace recode::explain {

std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s << std::setprecision(6) << v;
  return s.str();
}

std::string rectText(const raster::PixelRect& r) {
  std::ostringstream s;
  s << "[" << r.x0 << ", " << r.y0 << ", " << r.x1 << ", " << r.y1 << ")";
  return s.str();
}

std::string pointText(const Eigen::Vector3d& p) {
  // A stream rather than operator+: GCC 12 at -O3 warns falsely (-Wrestrict) on "(" + string.
  std::ostringstream s;
  s << "(" << formatNumber(p.x()) << ", " << formatNumber(p.y()) << ", " << formatNumber(p.z())
    << ")";
  return s.str();
}

std::string swatch(Rgb c) {
  return "<span class=\"sw\" style=\"background:" + hexColour(c) + "\"></span>";
}

}  // namespace recode::explain
