#pragma once
// Each of the kit's readings (kit/variants.hpp) classed once: the stage of the contract it
// departs at and the graphics APIs' freedom it takes, if any. diagnosis.cpp's stageOf and
// api_freedoms.cpp's freedomOf read this one table.

#include <optional>

#include "recode/conformance/api_freedoms.hpp"
#include "recode/conformance/stage.hpp"
#include "recode/kit/variants.hpp"

namespace recode::conformance {

struct ReadingClass {
  Stage stage;
  std::optional<Freedom> freedom;  // nullopt: it breaks a rule the APIs fix
};

// The class of a reading; Contract is classed as a depth value that takes no freedom.
[[nodiscard]] ReadingClass classOf(kit::Variant v);

}  // namespace recode::conformance
