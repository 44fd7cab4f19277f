#include "recode/conformance/stage.hpp"

#include <array>
#include <cstddef>

namespace recode::conformance {

namespace {

// The depth value and its quantisation answer to the same clauses.
constexpr std::string_view kDepthClause =
    "z is interpolated from the vertices' depths to about 1 part in 10^5 and converted to one of "
    "the two nearest 24-bit values (Vulkan, Depth Interpolation and Fixed-Point Data Conversions; "
    "OpenGL 4.5 sections 14.6.1, 2.3.4.1 and 2.3.5.2)";

constexpr StageInfo kStages[] = {
#define RECODE_STAGE_ROW(e, name, section, clause, colour) \
  {Stage::e, name, section, clause, colour},
    RECODE_CONFORMANCE_STAGES(RECODE_STAGE_ROW)
#undef RECODE_STAGE_ROW
};

constexpr bool inEnumOrder() {
  for (std::size_t i = 0; i < std::size(kStages); ++i)
    if (static_cast<std::size_t>(kStages[i].stage) != i)
      return false;
  return true;
}
static_assert(inEnumOrder(), "kStages is indexed by Stage");

}  // namespace

std::span<const StageInfo> allStages() {
  return kStages;
}

const StageInfo& infoOf(Stage s) {
  return kStages[static_cast<std::size_t>(s)];
}

std::string_view toString(Stage s) {
  return infoOf(s).name;
}

std::string_view contractSection(Stage s) {
  return infoOf(s).section;
}

}  // namespace recode::conformance
