#include "cli/view_axis_option.hpp"

namespace recode::app {

namespace {

const CLI::Validator kViewAxisRule(
    [](std::string& text) -> std::string {
      if (core::parseViewAxisRule(text))
        return "";
      return "unknown view axis rule '" + text + "': expected one of " +
             std::string(core::viewAxisRuleNames());
    },
    "RULE");

}  // namespace

CLI::Option* addViewAxisOption(CLI::App& cmd, std::string& rule) {
  return cmd
      .add_option("--view-axis", rule,
                  "the axis each pair is drawn along, at the same pixel size: scene (the "
                  "scene's, default), adaptive (the per-pair rule chosen by measurement, " +
                      std::string(core::toString(core::kAdaptiveViewAxisRule)) +
                      "), or a rule by name: fewest-mor, widest-overlap, separating, thin-overlap")
      ->check(kViewAxisRule)
      ->capture_default_str();
}

core::ViewAxisRule viewAxisRule(const std::string& rule) {
  return *core::parseViewAxisRule(rule);
}

}  // namespace recode::app
