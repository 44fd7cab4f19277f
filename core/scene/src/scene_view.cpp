// The "view" object of a scene file: axis, window, resolution, pixel size.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "scene_reader.hpp"

namespace recode::core::detail {

namespace {

using recode::json::childPath;
using recode::json::describeJsonValue;
using recode::json::jsonText;

ViewAxis readAxis(const JsonFieldReader& fields, const json& a, const std::string& path) {
  if (!a.is_string())
    fields.fail(path, "expected \"x\", \"y\" or \"z\", got " + describeJsonValue(a));
  const std::optional<ViewAxis> axis = parseViewAxis(a.get<std::string>());
  if (!axis)
    fields.fail(path, "expected \"x\", \"y\" or \"z\", got " + jsonText(a));
  return *axis;
}

ViewWindow readWindow(const JsonFieldReader& fields, const json& value, const std::string& path) {
  const json& w = fields.arrayOfSize(value, path, 4, "4 numbers [umin, vmin, umax, vmax]");
  ViewWindow window;
  const auto coordinate = [&](std::size_t i) {
    return fields.numberInRange(w[i], childPath(path, i), -kMaxCoordinate, kMaxCoordinate,
                                "world units");
  };
  window.umin = coordinate(0);
  window.vmin = coordinate(1);
  window.umax = coordinate(2);
  window.vmax = coordinate(3);
  if (!(window.umin < window.umax)) {
    fields.fail(path,
                "umin (" + jsonText(w[0]) + ") must be less than umax (" + jsonText(w[2]) + ")");
  }
  if (!(window.vmin < window.vmax)) {
    fields.fail(path,
                "vmin (" + jsonText(w[1]) + ") must be less than vmax (" + jsonText(w[3]) + ")");
  }
  // Coordinates within +-kMaxCoordinate cannot overflow; a side below kMinWindowSide would put
  // any object of ordinary size millions of pixels outside the frame.
  const double width = window.umax - window.umin, height = window.vmax - window.vmin;
  if (!(std::min(width, height) >= kMinWindowSide)) {
    fields.fail(path, std::string("the window's ") + (width < height ? "width " : "height ") +
                          recode::json::shortNumber(std::min(width, height)) +
                          " is below the smallest side, " +
                          recode::json::shortNumber(kMinWindowSide) + " world units");
  }
  return window;
}

}  // namespace

ViewSpec readView(const JsonFieldReader& fields, const json& v, const std::string& path) {
  fields.requireObject(v, path);
  fields.requireOnlyKeys(v, path, {"axis", "window", "resolution", "pixel_size"});
  ViewSpec spec;
  if (v.contains("axis"))
    spec.axis = readAxis(fields, v.at("axis"), childPath(path, "axis"));
  if (v.contains("window"))
    spec.window = readWindow(fields, v.at("window"), childPath(path, "window"));
  if (v.contains("resolution")) {
    const std::string p = childPath(path, "resolution");
    const json& r = fields.arrayOfSize(v.at("resolution"), p, 2, "2 integers [W, H]");
    spec.resolution = std::array<int, 2>{
        static_cast<int>(fields.integerInRange(r[0], childPath(p, 0), 1, 16384)),
        static_cast<int>(fields.integerInRange(r[1], childPath(p, 1), 1, 16384))};
  }
  if (v.contains("pixel_size")) {
    const std::string p = childPath(path, "pixel_size");
    if (spec.resolution)
      fields.fail(p, "cannot be given together with \"resolution\" (give one of the two)");
    spec.pixelSize =
        fields.positiveNumberUpTo(v.at("pixel_size"), p, kMaxCoordinate, "world units");
  }
  return spec;
}

}  // namespace recode::core::detail
