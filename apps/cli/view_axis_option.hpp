#pragma once
// --view-axis RULE, shared by `recode pair`, `recode run` and `recode verify`: the axis each
// pair is drawn along (core::ViewAxisRule; docs/algorithm.md, "Beyond the paper"). "scene",
// the default, leaves every output as it was.

#include <CLI/CLI.hpp>
#include <string>

#include "recode/refine/view_axis_choice.hpp"

namespace recode::app {

// Adds --view-axis to `cmd`, writing into `rule` (which must outlive the parse).
CLI::Option* addViewAxisOption(CLI::App& cmd, std::string& rule);

// The rule a value checked by the option names.
[[nodiscard]] core::ViewAxisRule viewAxisRule(const std::string& rule);

}  // namespace recode::app
