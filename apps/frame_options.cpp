#include "frame_options.hpp"

#include "pair_setup.hpp"

namespace recode::app {

core::FrameOverrides FrameOptions::overrides() const {
  core::FrameOverrides o;
  if (!resolution.empty())
    o = parseResolution(resolution);
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
                    ->check(CLI::PositiveNumber)
                    ->excludes(h.resolution);
  return h;
}

}  // namespace recode::app
