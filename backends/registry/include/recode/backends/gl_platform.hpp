#pragma once
// Where an exact GL device's context comes from: in every build, so that programs and oracles
// can name a platform (and say it is missing) without the GL back end.

#include <cstdint>
#include <optional>
#include <string_view>

namespace recode::backends {

// Auto takes EGL when its headless platform works and falls back to OSMesa, so the same
// program runs on Mesa's CPU driver and on a real GPU driver.
enum class GlPlatform : std::uint8_t { Auto, OsMesa, Egl };

// "auto", "osmesa", "egl".
[[nodiscard]] constexpr std::string_view toString(GlPlatform platform) {
  switch (platform) {
    case GlPlatform::Auto:
      return "auto";
    case GlPlatform::OsMesa:
      return "osmesa";
    case GlPlatform::Egl:
      return "egl";
  }
  return "unknown";
}

[[nodiscard]] constexpr std::optional<GlPlatform> parseGlPlatform(std::string_view name) {
  for (GlPlatform p : {GlPlatform::Auto, GlPlatform::OsMesa, GlPlatform::Egl}) {
    if (toString(p) == name)
      return p;
  }
  return std::nullopt;
}

// Which platforms this build can use (OSMesa and EGL are separate build options).
[[nodiscard]] bool glPlatformBuilt(GlPlatform platform);

// The platform that exact GL devices asking for `requested` get: makes the process's shared
// context for it once (Auto resolves to EGL or OSMesa). Throws as GlExactDevice's constructor
// does, and std::runtime_error naming the packages when the build has no exact GL device.
[[nodiscard]] GlPlatform resolveGlPlatform(GlPlatform requested);

}  // namespace recode::backends
