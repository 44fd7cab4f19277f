// CPU/GL parity: the golden vectors and the generated pair suite replayed on OSMesa, random
// constant-depth streams that must agree on every pixel, and the comparison shown to fail
// when a device or a result is wrong.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "recode/backends/gl_device.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/forwarding_device.hpp"
#include "recode/raster/golden.hpp"
#include "recode/verify/gl_parity.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;
using raster::CompareFunc;
using raster::Face;
using raster::StencilOp;
using raster::WindowVertex;

namespace {

// Forwards everything to an inner device, with hooks that make it wrong on purpose.
class AlteredDevice final : public raster::ForwardingDevice {
 public:
  explicit AlteredDevice(std::unique_ptr<raster::DepthStencilDevice> inner)
      : ForwardingDevice(std::move(inner)) {}

  std::function<raster::StencilOps(raster::StencilOps)> alterOps;
  std::function<void(int draw, std::vector<WindowVertex>&)> alterVertices;
  std::function<void(const raster::PixelRect&, std::vector<std::uint8_t>&)> alterStencil;

  void setStencilOps(Face face, const raster::StencilOps& ops) override {
    ForwardingDevice::setStencilOps(face, alterOps ? alterOps(ops) : ops);
  }
  void drawTriangles(std::span<const WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override {
    std::vector<WindowVertex> v(vertices.begin(), vertices.end());
    if (alterVertices)
      alterVertices(draws_, v);
    ++draws_;
    ForwardingDevice::drawTriangles(v, indices);
  }
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const raster::PixelRect& r) const override {
    auto s = ForwardingDevice::readStencil(r);
    if (alterStencil)
      alterStencil(r, s);
    return s;
  }

 private:
  int draws_ = 0;
};

raster::cmd::Draw rect(float x0, float y0, float x1, float y1, float z) {
  return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, {0, 1, 2, 0, 2, 3}};
}

std::vector<std::filesystem::path> goldenFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(RECODE_DATA_DIR "/golden"))
    if (entry.path().extension() == ".json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::uint32_t quantized(float z) {
  return raster::quantizeDepth(static_cast<double>(z));
}

// The float nearest 0.5 in the given direction whose 24-bit depth is `steps` away from 0.5's
// (float spacing there is about one depth step above 0.5 and half a step below).
float depthSteps(int steps) {
  const std::uint32_t target = quantized(0.5f) + static_cast<std::uint32_t>(steps);
  float z = 0.5f;
  while (quantized(z) != target)
    z = std::nextafter(z, steps > 0 ? 1.0f : 0.0f);
  return z;
}

}  // namespace

TEST_CASE("golden vectors replayed on OSMesa: stencil exact, depth within 2 LSB", "[gl][golden]") {
  const auto files = goldenFiles();
  REQUIRE(files.size() >= 7);
  long long pixels = 0, identical = 0, oneLsb = 0, twoLsb = 0;
  for (const auto& path : files) {
    INFO(path.filename().string());
    const raster::GoldenVector golden = raster::readGolden(path);
    const int w = golden.stream.width, h = golden.stream.height;
    backends::GlDevice gl(w, h);
    raster::replay(golden.stream.commands, gl);
    const auto depth = gl.readDepth({0, 0, w, h});
    const auto stencil = gl.readStencil({0, 0, w, h});
    REQUIRE(depth.size() == golden.depth.size());
    REQUIRE(stencil.size() == golden.stencil.size());
    CHECK(stencil == golden.stencil);
    for (std::size_t i = 0; i < depth.size(); ++i) {
      const std::uint32_t dd =
          depth[i] > golden.depth[i] ? depth[i] - golden.depth[i] : golden.depth[i] - depth[i];
      CHECK(dd <= verify::kGlDepthTolerance);
      identical += dd == 0;
      oneLsb += dd == 1;
      twoLsb += dd == 2;
    }
    pixels += static_cast<long long>(depth.size());

    // The comparison after every step agrees: nothing unexplained, no stencil ties.
    const verify::GlParityReport report = verify::compareStreamOnGl(golden.stream);
    CHECK(report.ok());
    CHECK(report.stencilTies == 0);
    CHECK(report.counts.identical + report.counts.depthTies == report.counts.pixels);
    CHECK(report.counts.pixels == static_cast<long long>(report.comparisons) * w * h);
  }
  CHECK(identical + oneLsb + twoLsb == pixels);
  CHECK(identical > pixels / 2);  // differences are the exception, not the rule
}

TEST_CASE("the generated pair suite replayed on CPU and GL: nothing unexplained", "[gl][suite]") {
  const auto suite = verify::generatePairSuite();  // 504 pairs at width 64
  REQUIRE(suite.size() == 504);
  verify::GlParityCounts total;
  long long compared = 0;
  for (const verify::SuitePair& pair : suite) {
    INFO(pair.label);
    core::PairRequest request;
    request.frame = pair.frame;
    const verify::GlParityReport report = verify::compareOnGl(pair.a, pair.b, request);
    if (!report.ok()) {
      const auto& e = report.examples.front();
      FAIL_CHECK("unexplained at command " << e.command << " pixel (" << e.x << ", " << e.y
                                           << "): stencil " << int(e.referenceStencil) << "/"
                                           << int(e.candidateStencil) << " depth "
                                           << e.referenceDepth << "/" << e.candidateDepth);
    }
    // The region is the pair's MOR, compared after every step.
    raster::CpuDevice cpu(pair.frame.width, pair.frame.height);
    const core::PairResult result = core::collidePair(cpu, pair.a, pair.b, request);
    CHECK(report.counts.pixels == static_cast<long long>(report.comparisons) * result.mor.area());
    CHECK(report.counts.identical + report.counts.depthTies + report.counts.unexplained ==
          report.counts.pixels);
    total += report.counts;
    compared += report.counts.pixels > 0;
  }
  CHECK(total.unexplained == 0);
  CHECK(compared > 250);  // most pairs have overlapping boxes and draw
  CHECK(total.identical > total.pixels / 2);
}

TEST_CASE("random constant-depth streams agree on GL pixel for pixel", "[gl][random]") {
  // Constant-depth triangles leave llvmpipe no rounding to do (its plane is a0 = z0 with zero
  // gradients), so coverage, every state and every op must agree exactly.
  std::mt19937 rng(20261123);
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const float depths[] = {0.0f, 0.125f, 0.25f, 0.5f, 0.75f, 1.0f};
  const int size = 24;
  for (int s = 0; s < 30; ++s) {
    raster::CommandStream stream;
    stream.width = size;
    stream.height = size - 5;
    for (int k = 0; k < 40; ++k) {
      switch (pick(9)) {
        case 0:
          stream.commands.emplace_back(raster::cmd::Scissor{
              {pick(size) - 4, pick(size) - 4, pick(size) + 8, pick(size) + 8}});
          break;
        case 1:
          stream.commands.emplace_back(raster::cmd::ClearDepth{depths[pick(6)]});
          break;
        case 2:
          stream.commands.emplace_back(raster::cmd::ClearStencil{std::uint8_t(pick(256))});
          break;
        case 3:
          stream.commands.emplace_back(raster::cmd::DepthFunc{CompareFunc(pick(8))});
          stream.commands.emplace_back(raster::cmd::DepthWriteMask{pick(3) != 0});
          break;
        case 4:
          stream.commands.emplace_back(
              raster::cmd::StencilFunc{CompareFunc(pick(8)), std::uint8_t(pick(256)),
                                       std::uint8_t(pick(2) ? 0xFF : pick(256))});
          break;
        case 5:
          stream.commands.emplace_back(raster::cmd::StencilOpsCmd{
              Face(pick(3)), {StencilOp(pick(8)), StencilOp(pick(8)), StencilOp(pick(8))}});
          break;
        case 6:
          stream.commands.emplace_back(
              raster::cmd::StencilWriteMask{std::uint8_t(pick(2) ? 0xFF : pick(256))});
          stream.commands.emplace_back(raster::cmd::Cull{raster::CullMode(pick(3))});
          break;
        default: {
          // A few triangles on the 1/256 grid, some reaching outside the framebuffer, with
          // either winding, all at one depth.
          raster::cmd::Draw draw;
          const float z = depths[pick(6)];
          for (int t = 0; t < 1 + pick(4); ++t) {
            for (int v = 0; v < 3; ++v) {
              const auto coordinate = [&] {
                return float(pick(256 * (size + 16)) - 256 * 8) / 256.0f;
              };
              draw.vertices.push_back({coordinate(), coordinate(), z});
              draw.indices.push_back(static_cast<std::uint32_t>(draw.indices.size()));
            }
          }
          stream.commands.emplace_back(std::move(draw));
        }
      }
    }
    const verify::GlParityReport report = verify::compareStreamOnGl(stream);
    INFO("stream " << s);
    CHECK(report.counts.pixels > 0);
    CHECK(report.counts.identical == report.counts.pixels);
  }
}

TEST_CASE("GL parity reports a wrong device, a changed CPU result and a moved vertex",
          "[gl][failure]") {
  raster::CommandStream stream;
  stream.width = stream.height = 8;
  stream.commands = {
      raster::cmd::DepthFunc{CompareFunc::Always}, raster::cmd::ClearStencil{255},
      raster::cmd::StencilOpsCmd{Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr}},
      rect(2, 2, 6, 6, 0.5f)};

  SECTION("a GL device that wraps where it should saturate") {
    raster::CpuDevice cpu(8, 8);
    AlteredDevice gl(std::make_unique<backends::GlDevice>(8, 8));
    gl.alterOps = [](raster::StencilOps ops) {
      if (ops.depthPass == StencilOp::Incr)
        ops.depthPass = StencilOp::IncrWrap;
      return ops;
    };
    const auto report = verify::compareStreamOnDevices(stream, cpu, gl);
    CHECK_FALSE(report.ok());
    CHECK(report.counts.unexplained == 16);  // the 4 x 4 pixels of the quad, once
    REQUIRE_FALSE(report.examples.empty());
    CHECK(report.examples[0].command == 3);
    CHECK(report.examples[0].referenceStencil == 255);
    CHECK(report.examples[0].candidateStencil == 0);
  }

  SECTION("a CPU result changed at one pixel") {
    AlteredDevice cpu(std::make_unique<raster::CpuDevice>(8, 8));
    backends::GlDevice gl(8, 8);
    cpu.alterStencil = [](const raster::PixelRect& r, std::vector<std::uint8_t>& s) {
      if (r.x0 <= 3 && 3 < r.x1 && r.y0 <= 2 && 2 < r.y1)
        s[static_cast<std::size_t>((2 - r.y0) * r.width() + (3 - r.x0))] ^= 0x10;
    };
    const auto report = verify::compareStreamOnDevices(stream, cpu, gl);
    // Seen at every comparison: the fresh state, the clear and the draw.
    CHECK(report.comparisons == 3);
    CHECK(report.counts.unexplained == 3);
    REQUIRE(report.examples.size() == 3);
    CHECK(report.examples[0].x == 3);
    CHECK(report.examples[0].y == 2);
    CHECK(report.examples[2].referenceStencil == (255 ^ 0x10));
    CHECK(report.examples[2].candidateStencil == 255);
  }

  SECTION("a vertex moved by one pixel on the GL side only") {
    stream.commands[1] = raster::cmd::ClearStencil{0};
    raster::CpuDevice cpu(8, 8);
    AlteredDevice gl(std::make_unique<backends::GlDevice>(8, 8));
    gl.alterVertices = [](int, std::vector<WindowVertex>& v) {
      for (auto& p : v)
        p.x += 1.0f;
    };
    const auto report = verify::compareStreamOnDevices(stream, cpu, gl);
    // Columns 2 and 6 of rows 2..5 differ: covered on one side only.
    CHECK(report.counts.unexplained == 8);
  }
}

TEST_CASE("stencil differences are explained only where a depth test was within reach",
          "[gl][ties]") {
  // Two coplanar quads at z = 0.5 on an 8 x 8 frame: the first writes depth and stencil 1, the
  // second passes LEQUAL exactly (equal depths) and increments. The candidate is a CPU device
  // whose second quad is moved by some depth steps: what GL's float rounding could do.
  // The flat plane's tolerance (docs/verification.md): 1 + 6 |z0| = 4 LSB.
  raster::CommandStream stream;
  stream.width = stream.height = 8;
  stream.commands = {
      raster::cmd::StencilFunc{CompareFunc::Always, 1, 0xFF},
      raster::cmd::StencilOpsCmd{Face::Both,
                                 {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace}},
      rect(0, 0, 8, 8, 0.5f),
      raster::cmd::DepthFunc{CompareFunc::LEqual},
      raster::cmd::StencilOpsCmd{Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr}},
      rect(0, 0, 8, 8, 0.5f)};
  const auto run = [&](float z) {
    raster::CpuDevice cpu(8, 8);
    AlteredDevice other(std::make_unique<raster::CpuDevice>(8, 8));
    other.alterVertices = [z](int draw, std::vector<WindowVertex>& v) {
      if (draw == 1)
        for (auto& p : v)
          p.z = z;
    };
    return verify::compareStreamOnDevices(stream, cpu, other);
  };
  const std::uint32_t half = quantized(0.5f);

  SECTION("one step farther: LEQUAL fails, the stencil differs at a decision made at margin 0") {
    const auto report = run(depthSteps(1));
    CHECK(report.ok());
    CHECK(report.stencilTies == 64);
    CHECK(report.counts.depthTies == 64);
  }
  SECTION("three steps nearer: passes, depth within the plane's 4 LSB") {
    const auto report = run(depthSteps(-3));
    CHECK(report.ok());
    CHECK(report.stencilTies == 0);
    CHECK(report.wideDepthTies == 64);
    CHECK(report.maxDepthDifference == 3);
  }
  SECTION("far beyond the tolerance: the written depth gives it away") {
    const float z = 0.499f;
    REQUIRE(half - quantized(z) > 10000);
    const auto report = run(z);
    CHECK(report.counts.unexplained == 64);
  }
  SECTION("with the plane bound off, 3 steps exceed the 2 LSB floor") {
    const float z = depthSteps(-3);
    raster::CpuDevice cpu(8, 8);
    AlteredDevice other(std::make_unique<raster::CpuDevice>(8, 8));
    other.alterVertices = [z](int draw, std::vector<WindowVertex>& v) {
      if (draw == 1)
        for (auto& p : v)
          p.z = z;
    };
    verify::GlParityOptions options;
    options.planeErrorBound = false;
    const auto report = verify::compareStreamOnDevices(stream, cpu, other, options);
    CHECK(report.counts.unexplained == 64);
  }
}

TEST_CASE("GL parity checks its inputs", "[gl][errors]") {
  raster::CommandStream stream;
  stream.width = 8;
  stream.height = 4;
  raster::CpuDevice cpu(8, 4);
  raster::CpuDevice wrongSize(4, 8);
  CHECK_THROWS_AS(verify::compareStreamOnDevices(stream, cpu, wrongSize), std::invalid_argument);
  // A bad draw in the stream is the devices' error, reported as theirs.
  stream.commands.emplace_back(raster::cmd::Draw{{{0, 0, 0.5f}, {1, 0, 0.5f}}, {0, 1, 2}});
  CHECK_THROWS_AS(verify::compareStreamOnGl(stream), std::invalid_argument);
  // A region outside the framebuffer compares nothing.
  raster::CommandStream empty;
  empty.width = empty.height = 4;
  empty.commands.emplace_back(rect(0, 0, 4, 4, 0.5f));
  verify::GlParityOptions options;
  options.region = raster::PixelRect{10, 10, 20, 20};
  const auto report = verify::compareStreamOnGl(empty, options);
  CHECK(report.counts.pixels == 0);
  CHECK(report.ok());
}
