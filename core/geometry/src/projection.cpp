// The view axis names of scene files and output.
#include "recode/geometry/projection.hpp"

namespace recode::core {

std::string_view toString(ViewAxis axis) {
  switch (axis) {
    case ViewAxis::X:
      return "x";
    case ViewAxis::Y:
      return "y";
    case ViewAxis::Z:
      break;
  }
  return "z";
}

std::optional<ViewAxis> parseViewAxis(std::string_view name) {
  for (const ViewAxis axis : {ViewAxis::X, ViewAxis::Y, ViewAxis::Z})
    if (name == toString(axis))
      return axis;
  return std::nullopt;
}

}  // namespace recode::core
