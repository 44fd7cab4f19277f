#pragma once
// The 24-bit depth quantisation of docs/rasterization.md, section 5, under each rounding a
// variant reads into it (plane_recipe.hpp).

#include <cstdint>

#include "plane_recipe.hpp"

namespace recode::kit::detail {

// 0 for z <= 0 or NaN, 16777215 for z >= 1, else z * 16777215 (or 16777216) rounded as `r`
// says.
[[nodiscard]] std::uint32_t quantiseWith(Rounding r, double z);

}  // namespace recode::kit::detail
