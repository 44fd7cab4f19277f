#include "pair_request.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "recode/refine/pair_mode.hpp"
#include "recode/refine/view_axis_choice.hpp"

namespace recode::wasm {

namespace {

using Json = nlohmann::json;

[[noreturn]] void refuse(const std::string& key, const Json& value, const std::string& rule) {
  throw std::invalid_argument("request." + key + ": " + value.dump() + ": " + rule);
}

std::string text(const Json& j, const std::string& key) {
  if (!j.is_string())
    refuse(key, j, "expected a string");
  return j.get<std::string>();
}

bool flag(const Json& j, const std::string& key) {
  if (!j.is_boolean())
    refuse(key, j, "expected true or false");
  return j.get<bool>();
}

}  // namespace

PairRequestText readPairRequest(const std::string& json) {
  const Json request = Json::parse(json, nullptr, false);
  if (request.is_discarded() || !request.is_object())
    throw std::invalid_argument("request: expected one JSON object");
  PairRequestText r;
  explain::PairRunOptions& o = r.options;
  for (const auto& [key, value] : request.items()) {
    if (key == "scene") {
      if (!value.is_null())
        o.scene = text(value, key);
    } else if (key == "resolution") {
      const core::FrameOverrides size = explain::parseResolution(text(value, key));
      o.overrides.width = size.width;
      o.overrides.height = size.height;
    } else if (key == "pixel_size") {
      if (!value.is_number() || !(value.get<double>() > 0) || !std::isfinite(value.get<double>()))
        refuse(key, value, "expected a finite number > 0");
      o.overrides.pixelSize = value.get<double>();
    } else if (key == "mor") {
      const auto mor = core::parseMorMode(text(value, key));
      if (!mor)
        refuse(key, value, "expected min, max or full");
      o.mor = *mor;
    } else if (key == "contact") {
      o.contact = flag(value, key);
    } else if (key == "box_test") {
      o.boxTest = flag(value, key);
    } else if (key == "normal") {
      o.normal = flag(value, key);
    } else if (key == "pixel") {
      o.pixel = text(value, key);
    } else if (key == "mode") {
      const auto mode = core::parsePairMode(text(value, key));
      if (!mode)
        refuse(key, value, "expected reference, adaptive, conservative or skip-apart");
      o.mode = *mode;
    } else if (key == "view_axis") {
      const auto rule = core::parseViewAxisRule(text(value, key));
      if (!rule)
        refuse(key, value, "expected one of " + std::string(core::viewAxisRuleNames()));
      o.axisRule = *rule;
    } else if (key == "timing") {
      r.timing = flag(value, key);
    } else if (key == "dump_cases") {
      r.dumpCases = text(value, key);
    } else {
      refuse(key, value,
             "unknown key (expected scene, resolution, pixel_size, mor, contact, box_test, "
             "normal, pixel, mode, view_axis, timing or dump_cases)");
    }
  }
  if (o.overrides.width && o.overrides.pixelSize)
    throw std::invalid_argument("request: give resolution or pixel_size, not both");
  if (o.normal && !o.contact)
    throw std::invalid_argument("request.normal: needs the contact passes (contact: true)");
  return r;
}

}  // namespace recode::wasm
