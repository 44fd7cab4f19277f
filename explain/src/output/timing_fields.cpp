#include "output/timing_fields.hpp"

#include <array>
#include <string>
#include <string_view>

namespace recode::output {

namespace {

constexpr std::array<std::string_view, 11> kTimingKeys = {
    "timing_us", "timing_steps_us", "frame_us", "collision_us", "TTF_s",  "ATF_ms",
    "DTF_ms",    "TTC_s",           "ATC_ms",   "DTC_ms",       "seconds"};

}  // namespace

void removeTimingFields(nlohmann::ordered_json& j) {
  if (j.is_object()) {
    for (std::string_view key : kTimingKeys)
      j.erase(std::string(key));
  }
  if (j.is_structured()) {
    for (nlohmann::ordered_json& child : j)
      removeTimingFields(child);
  }
}

}  // namespace recode::output
