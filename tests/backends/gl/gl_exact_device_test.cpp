// What is the exact GL device's own: the parity check's power to report a device that differs,
// and what the shared context must not leak between exact and fixed-function devices, on every
// context platform this build has. The contract itself (golden vectors, random streams, the
// pair suite, clears, two devices' states kept apart, errors) is the conformance suite's, which
// runs on every exact device (tests/backends/device_conformance_test.cpp).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact_test_streams.hpp"
#include "recode/backends/gl_device.hpp"
#include "recode/backends/gl_exact_device.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"
#include "recode/verify/exact_parity.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;
using backends::GlExactDevice;
using backends::GlPlatform;
using raster::CompareFunc;
using raster::Face;
using raster::StencilOp;
using raster::WindowVertex;

namespace {

using verify::testing::describe;
using verify::testing::goldenFiles;
using verify::testing::randomStream;

std::vector<backends::GlPlatform> platforms() {
  std::vector<std::string> unavailable;
  const std::vector<backends::GlPlatform> list = verify::testing::exactGlPlatformsHere(unavailable);
  for (const std::string& why : unavailable)
    WARN(why);
  return list;
}

}  // namespace

TEST_CASE("exact parity reports a device that differs", "[gl-exact][errors]") {
  // The comparer itself must be able to fail: the same stream with one vertex moved by one
  // sub-pixel step, replayed on a second CPU device, differs somewhere.
  raster::CommandStream stream;
  stream.width = stream.height = 16;
  stream.commands.emplace_back(
      raster::cmd::Draw{{{1.0f, 1.0f, 0.2f}, {15.0f, 2.0f, 0.9f}, {3.0f, 14.0f, 0.5f}}, {0, 1, 2}});
  raster::CommandStream moved = stream;
  std::get<raster::cmd::Draw>(moved.commands[0]).vertices[2].z = 0.51f;
  raster::CpuDevice reference(16, 16);
  raster::CpuDevice candidate(16, 16);
  raster::replay(moved.commands, candidate);  // the candidate starts from a wrong state
  const auto report = verify::compareStreamExactly(stream, reference, candidate);
  CHECK_FALSE(report.ok());
  CHECK(report.counts.different > 0);
  REQUIRE_FALSE(report.examples.empty());
  CHECK(report.examples.front().command == -1);
}

#ifdef RECODE_HAVE_OSMESA
TEST_CASE("exact GL devices keep working between uses of fixed-function GL devices", "[gl-exact]") {
  // OSMesa and Mesa's EGL share one dispatch: a fixed-function backends::GlDevice made, used and
  // destroyed between two uses of an exact device takes the dispatch over behind the exact device's
  // back (this once made every exact call after `recode verify --gl`'s first pair read zeros).
  for (backends::GlPlatform platform : platforms()) {
    INFO("platform " << backends::toString(platform));
    backends::GlExactDevice exact(4, 4, platform);
    const WindowVertex v[3] = {{0, 0, 0.25f}, {4, 0, 0.25f}, {0, 4, 0.25f}};
    const std::uint32_t i[3] = {0, 1, 2};
    for (int round = 0; round < 3; ++round) {
      {
        backends::GlDevice fixed(4, 4);
        fixed.drawTriangles(v, i);
        CHECK(fixed.readDepth({0, 0, 1, 1}).at(0) == 4194304u);
      }
      exact.clearDepth(1.0);
      exact.drawTriangles(v, i);
      CHECK(exact.readDepth({0, 0, 1, 1}).at(0) == 4194304u);  // 0.25 (2^24 - 1), rounded
      CHECK(exact.readDepth({3, 3, 4, 4}).at(0) == 16777215u);
    }
  }
}
#endif
