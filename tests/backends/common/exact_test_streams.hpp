#pragma once
// What the exact devices' tests share (GL and Vulkan): the golden vector files, a one-line
// description of a parity report's first difference, and random command streams that exercise
// every state, sloped planes, slivers, the guard band and the fill rule.

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "recode/raster/command_stream.hpp"
#include "recode/verify/exact_parity.hpp"
#if RECODE_HAVE_GL_EXACT
#include "recode/backends/gl_exact_device.hpp"
#endif

namespace recode::verify::testing {

// Every *.json under data/golden, recursively, sorted.
[[nodiscard]] std::vector<std::filesystem::path> goldenFiles();

// "command k pixel (x, y): depth a vs b, stencil c vs d" for the first difference.
[[nodiscard]] std::string describe(const ExactParityReport& report);

// A random stream of 30 commands on a width x height framebuffer: every state, sloped planes
// with z anywhere in [0, 1], slivers, vertices far outside the framebuffer (up to the +-32768
// guard band), random sub-pixel positions and positions on pixel centres and edges.
[[nodiscard]] raster::CommandStream randomStream(std::mt19937& rng, int width, int height);

#if RECODE_HAVE_GL_EXACT
// The exact GL device's context platforms to test here: OSMesa when built (it is what this
// machine has: a failure to make its context fails the tests); EGL when built and its headless
// platform gives a context, else why not is added to `unavailable`.
[[nodiscard]] std::vector<backends::GlPlatform> exactGlPlatformsHere(
    std::vector<std::string>& unavailable);
#endif

}  // namespace recode::verify::testing
