#include "cli/frame_options.hpp"

#include <charconv>
#include <cmath>

#include "pair/pair_setup.hpp"

namespace recode::app {

namespace {

// A pixel size must be a positive finite number: CLI11's PositiveNumber lets NaN through (every
// comparison with it is false), and a NaN pixel size was then silently ignored.
const CLI::Validator kPositiveFiniteNumber(
    [](std::string& text) -> std::string {
      double value = 0.0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
          !(value > 0.0)) {
        return "expected a positive finite number of world units, got " + text;
      }
      return "";
    },
    "POSITIVE");

}  // namespace

core::FrameOverrides FrameOptions::overrides() const {
  core::FrameOverrides o;
  if (!resolution.empty())
    o = explain::parseResolution(resolution);
  if (pixelSize > 0.0)
    o.pixelSize = pixelSize;
  return o;
}

core::MorMode FrameOptions::mor() const {
  return core::parseMorMode(morName).value();  // CLI11 checked the name
}

FrameOptionHandles addFrameOptions(CLI::App& cmd, FrameOptions& values,
                                   const FrameOptionHelp& help) {
  FrameOptionHandles h;
  h.mor = cmd.add_option("--mor", values.morName, help.mor)
              ->check(CLI::IsMember({"min", "max", "full"}))
              ->capture_default_str();
  h.resolution = cmd.add_option("--resolution", values.resolution, help.resolution);
  h.pixelSize = cmd.add_option("--pixel-size", values.pixelSize, help.pixelSize)
                    ->check(kPositiveFiniteNumber)
                    ->excludes(h.resolution);
  return h;
}

}  // namespace recode::app
