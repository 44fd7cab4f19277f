#include "demo_command.hpp"

#include <Eigen/Geometry>
#include <array>
#include <chrono>
#include <iomanip>
#include <iostream>

#include "recode/core/generators.hpp"
#include "recode/core/validate.hpp"
#include "recode/core/view.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/facing_counts.hpp"

namespace recode::app {

namespace {

struct DemoOptions {
  int width = 120;
  int height = 218;
  int segments = 32;
  double overlap = 0.25;
  bool picture = true;
};

struct Cones {
  core::TriangleMesh a, b;
};

// Cone A: base at z = 0, apex at z = 2. Cone B: the same cone turned upside down, its apex
// `overlap` below A's apex.
Cones makeCones(int segments, double overlap) {
  const core::TriangleMesh cone = core::makeCone(1.0, 2.0, segments);
  Eigen::Isometry3d flip = Eigen::Isometry3d::Identity();
  flip.translate(Eigen::Vector3d(0.0, 0.0, 4.0 - overlap));
  flip.rotate(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  return {cone, core::transformed(cone, flip)};
}

int runDemo(const DemoOptions& o) {
  using namespace raster;
  const Cones cones = makeCones(o.segments, o.overlap);
  core::validateConvexBlock(cones.a, "cone A");
  core::validateConvexBlock(cones.b, "cone B");

  // Side view along x: the image plane is (y, z), so the cones appear as two triangles.
  const core::Aabb ba = core::boundingBox(cones.a), bb = core::boundingBox(cones.b);
  const double depthMin = std::min(ba.min.x(), bb.min.x()) - 0.1;
  const double depthMax = std::max(ba.max.x(), bb.max.x()) + 0.1;
  const core::OrthoView view(core::ViewAxis::X, {-1.2, -0.2, 1.2, 4.15}, o.width, o.height,
                             depthMin, depthMax);
  const auto va = view.toWindow(cones.a), vb = view.toWindow(cones.b);
  const auto ia = core::triangleIndices(cones.a), ib = core::triangleIndices(cones.b);

  CpuDevice dev(o.width, o.height);
  const long long crackA = countFacingFragments(dev, va, ia).unequalPixels();
  const long long crackB = countFacingFragments(dev, vb, ib).unequalPixels();
  dev.resetCounters();

  const auto start = std::chrono::steady_clock::now();
  // RenderSetZ(A, >=): depth cleared to 0, A's back faces with GEQUAL leave A's far depth
  // (Amax) in the depth buffer and stencil 1 under A.
  dev.setScissor({0, 0, o.width, o.height});
  dev.setDepthWriteMask(true);
  dev.clearDepth(0.0);
  dev.clearStencil(0);
  dev.setCullMode(CullMode::Front);
  dev.setDepthFunc(CompareFunc::GEqual);
  dev.setStencilFunc(CompareFunc::Always, 1, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
  dev.drawTriangles(va, ia);
  // RenderTestZ(B, <=): every face of B no farther than Amax adds one where A was drawn
  // (stencil >= 1, i.e. ref 1 <= stencil).
  dev.setCullMode(CullMode::None);
  dev.setDepthFunc(CompareFunc::LEqual);
  dev.setDepthWriteMask(false);
  dev.setStencilFunc(CompareFunc::LEqual, 1, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr});
  dev.drawTriangles(vb, ib);
  const auto stencil = dev.readStencil({0, 0, o.width, o.height});
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();

  std::array<long long, 256> histogram{};
  for (std::uint8_t s : stencil)
    ++histogram[s];

  std::cout << "RECODE raster demo: two cones tip to tip (apexes overlap by " << o.overlap
            << "), side view along x, " << o.width << "x" << o.height << " pixels\n"
            << "  cone A " << cones.a.triangles.size() << " triangles, cone B "
            << cones.b.triangles.size() << " triangles (validated closed, outward, convex)\n"
            << "  watertightness: pixels with front != back fragments: A " << crackA << ", B "
            << crackB << "\n"
            << "  passes RenderSetZ(A, GEQUAL) + RenderTestZ(B, LEQUAL): " << std::fixed
            << std::setprecision(0) << us << " us, " << dev.counters().fragments << " fragments\n"
            << "  stencil after the two passes (DESIGN.md section 5):\n"
            << "    0  outside A                                  " << histogram[0] << " px\n"
            << "    1  A, no face of B at or before A's back      " << histogram[1] << " px\n"
            << "    2  one face of B at or before A's back        " << histogram[2]
            << " px  <- B enters A's depth interval: interference candidates\n"
            << "    3  both faces of B at or before A's back      " << histogram[3] << " px\n";
  if (o.picture) {
    std::cout << "  stencil picture ('.' 0, '-' 1, '#' 2, '=' 3), top row first:\n";
    const int cellW = std::max(1, o.width / 40), cellH = std::max(1, o.height / 36);
    for (int y = o.height - 1 - cellH / 2; y >= 0; y -= cellH) {
      std::string line = "    ";
      for (int x = cellW / 2; x < o.width; x += cellW) {
        const std::uint8_t s = stencil[static_cast<std::size_t>(y) * o.width + x];
        line += s == 0 ? '.' : s == 1 ? '-' : s == 2 ? '#' : '=';
      }
      std::cout << line << '\n';
    }
  }
  const bool ok = crackA == 0 && crackB == 0;
  if (!ok)
    std::cout << "  ERROR: a closed mesh was not drawn watertight\n";
  return ok ? 0 : 1;
}

}  // namespace

void addDemoCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<DemoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "demo",
      "Run RECODE's first two passes on the CPU depth/stencil machine for two cones tip "
      "to tip and print the stencil buffer");
  cmd->add_option("--width", opts->width, "framebuffer width in pixels")
      ->check(CLI::Range(1, raster::kMaxFramebufferSize))
      ->capture_default_str();
  cmd->add_option("--height", opts->height, "framebuffer height in pixels")
      ->check(CLI::Range(1, raster::kMaxFramebufferSize))
      ->capture_default_str();
  cmd->add_option("--segments", opts->segments, "segments around each cone")
      ->check(CLI::Range(3, 100000))
      ->capture_default_str();
  cmd->add_option("--overlap", opts->overlap, "how far the apexes overlap along z (world units)")
      ->check(CLI::Range(-1.0, 1.0))
      ->capture_default_str();
  cmd->add_flag("!--no-picture", opts->picture, "do not print the stencil picture");
  cmd->callback([opts, &exitCode]() { exitCode = runDemo(*opts); });
}

}  // namespace recode::app
