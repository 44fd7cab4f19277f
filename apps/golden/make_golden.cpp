// Writes the golden vectors of data/golden/: small command streams that exercise the fill
// rule, the depth plane and quantisation, the stencil ops and masks, culling and scissoring,
// with the buffers the CPU reference produces. tests/raster/golden_test.cpp replays them on
// the CPU device and on an independent per-pixel model; GPU back ends replay them too.
//
//   recode-make-golden OUT_DIR

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/golden.hpp"

using namespace recode::raster;

namespace {

struct Case {
  std::string name;
  std::string description;
  int width;
  int height;
  std::vector<Command> commands;
};

cmd::Draw triangles(std::vector<WindowVertex> v, std::vector<std::uint32_t> i) {
  return cmd::Draw{std::move(v), std::move(i)};
}

const StencilOps kIncr{StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap};

std::vector<Command> counting() {
  return {cmd::DepthFunc{CompareFunc::Always}, cmd::DepthWriteMask{false},
          cmd::StencilFunc{CompareFunc::Always, 0, 0xFF}, cmd::StencilOpsCmd{Face::Both, kIncr}};
}

// An octahedron around (cx, cy) with radius r in pixels and depth centre cz, depth radius rz;
// outward faces, counter-clockwise seen from +z (the viewer looks down -z; depth grows away).
cmd::Draw octahedron(float cx, float cy, float r, float cz, float rz) {
  const auto q = [](float v) { return snapToSubpixel(v); };
  // Window depth grows away from the viewer, so the vertex nearest the viewer has cz - rz.
  std::vector<WindowVertex> v = {{q(cx + r), q(cy), cz},  {q(cx), q(cy + r), cz},
                                 {q(cx - r), q(cy), cz},  {q(cx), q(cy - r), cz},
                                 {q(cx), q(cy), cz - rz}, {q(cx), q(cy), cz + rz}};
  // Top (near, index 4) faces counter-clockwise in the window; bottom ones clockwise.
  std::vector<std::uint32_t> i = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4,
                                  1, 0, 5, 2, 1, 5, 3, 2, 5, 0, 3, 5};
  return triangles(std::move(v), std::move(i));
}

// A declarative table, one block per golden vector: long, but each block reads on its own.
std::vector<Case> cases() {
  std::vector<Case> out;
  {
    Case c{"fill_square",
           "Two triangles of the square [2.5,6.5]^2, edges through pixel centres:"
           " left column and bottom row drawn, right and top not, diagonal once.",
           10, 10, counting()};
    c.commands.push_back(
        triangles({{2.5f, 2.5f, 0.5f}, {6.5f, 2.5f, 0.5f}, {6.5f, 6.5f, 0.5f}, {2.5f, 6.5f, 0.5f}},
                  {0, 1, 2, 0, 2, 3}));
    out.push_back(std::move(c));
  }
  {
    Case c{"fill_fan",
           "Seven triangles around a vertex at the centre of pixel (8, 8), both"
           " windings: every pixel of the fan exactly once.",
           17, 17, counting()};
    std::vector<WindowVertex> v = {{8.5f, 8.5f, 0.5f}};
    std::vector<std::uint32_t> idx;
    for (int k = 0; k < 7; ++k) {
      const double a = 2.0 * M_PI * (k + 0.3 * (k % 3)) / 7.0;
      v.push_back(
          {snapToSubpixel(8.5 + 7.3 * std::cos(a)), snapToSubpixel(8.5 + 7.3 * std::sin(a)), 0.5f});
    }
    for (std::uint32_t k = 0; k < 7; ++k) {
      const std::uint32_t a = 1 + k, b = 1 + (k + 1) % 7;
      if (k % 2 == 0) {
        idx.insert(idx.end(), {0, a, b});
      } else {
        idx.insert(idx.end(), {b, a, 0});
      }
    }
    c.commands.push_back(triangles(std::move(v), std::move(idx)));
    out.push_back(std::move(c));
  }
  {
    Case c{"depth_less_crossing",
           "Two sloped triangles that cross in depth, depth func LESS,"
           " stencil REPLACE with refs 1 and 2: the depth plane, its quantisation and the"
           " depth test decide which one each pixel keeps.",
           24,
           24,
           {}};
    c.commands.push_back(cmd::ClearDepth{1.0});
    c.commands.push_back(cmd::StencilFunc{CompareFunc::Always, 1, 0xFF});
    c.commands.push_back(
        cmd::StencilOpsCmd{Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace}});
    c.commands.push_back(
        triangles({{1.25f, 2.0f, 0.1f}, {22.75f, 3.5f, 0.9f}, {4.0f, 21.0f, 0.1f}}, {0, 1, 2}));
    c.commands.push_back(cmd::StencilFunc{CompareFunc::Always, 2, 0xFF});
    c.commands.push_back(triangles(
        {{22.0f, 1.0f, 0.2f}, {20.5f, 22.5f, 0.7f}, {1.00390625f, 12.0f, 0.6f}}, {0, 1, 2}));
    out.push_back(std::move(c));
  }
  {
    Case c{"two_sided_octahedron",
           "A closed octahedron counted with INCR on front faces and"
           " INCR_WRAP on back faces inside a scissor: 2 inside the silhouette, 0 outside;"
           " depth holds the back surface (depth func GEQUAL after clearing to 0).",
           32,
           32,
           {}};
    c.commands.push_back(cmd::Scissor{{3, 2, 29, 30}});
    c.commands.push_back(cmd::ClearDepth{0.0});
    c.commands.push_back(cmd::ClearStencil{0});
    c.commands.push_back(cmd::DepthFunc{CompareFunc::GEqual});
    c.commands.push_back(
        cmd::StencilOpsCmd{Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr}});
    c.commands.push_back(
        cmd::StencilOpsCmd{Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap}});
    c.commands.push_back(octahedron(16.3f, 15.6f, 13.1f, 0.5f, 0.3f));
    out.push_back(std::move(c));
  }
  {
    Case c{"recode_passes",
           "The RECODE pattern on two octahedra: within a scissor, A's back"
           " faces with GEQUAL set depth to Amax and stencil to 1; then B with LEQUAL, no depth"
           " writes, INCR where stencil >= 1.",
           32,
           32,
           {}};
    c.commands.push_back(cmd::Scissor{{4, 4, 28, 28}});
    c.commands.push_back(cmd::ClearDepth{0.0});
    c.commands.push_back(cmd::ClearStencil{0});
    c.commands.push_back(cmd::Cull{CullMode::Front});
    c.commands.push_back(cmd::DepthFunc{CompareFunc::GEqual});
    c.commands.push_back(cmd::StencilFunc{CompareFunc::Always, 1, 0xFF});
    c.commands.push_back(
        cmd::StencilOpsCmd{Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace}});
    c.commands.push_back(octahedron(13.0f, 14.0f, 10.0f, 0.5f, 0.2f));
    c.commands.push_back(cmd::Cull{CullMode::None});
    c.commands.push_back(cmd::DepthFunc{CompareFunc::LEqual});
    c.commands.push_back(cmd::DepthWriteMask{false});
    c.commands.push_back(cmd::StencilFunc{CompareFunc::LEqual, 1, 0xFF});
    c.commands.push_back(
        cmd::StencilOpsCmd{Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr}});
    c.commands.push_back(octahedron(19.0f, 17.0f, 9.0f, 0.45f, 0.15f));
    out.push_back(std::move(c));
  }
  {
    Case c{"masks_and_cull",
           "Stencil value mask 0x0F and write mask 0x3C, INVERT and DECR_WRAP,"
           " culling of back faces, and a depth-masked clear that must not change depth.",
           16,
           16,
           {}};
    c.commands.push_back(cmd::ClearStencil{0xA5});
    c.commands.push_back(cmd::ClearDepth{0.75});
    c.commands.push_back(cmd::DepthWriteMask{false});
    c.commands.push_back(cmd::ClearDepth{0.0});
    c.commands.push_back(cmd::DepthWriteMask{true});
    c.commands.push_back(cmd::StencilFunc{CompareFunc::Equal, 0x05, 0x0F});
    c.commands.push_back(cmd::StencilWriteMask{0x3C});
    c.commands.push_back(
        cmd::StencilOpsCmd{Face::Front, {StencilOp::DecrWrap, StencilOp::Zero, StencilOp::Invert}});
    c.commands.push_back(cmd::Cull{CullMode::Back});
    c.commands.push_back(triangles(
        {{0.5f, 0.5f, 0.6f}, {15.5f, 0.5f, 0.6f}, {0.5f, 15.5f, 0.9f}, {15.5f, 15.5f, 0.2f}},
        {0, 1, 2, 1, 3, 2, 0, 2, 3}));
    out.push_back(std::move(c));
  }
  {
    Case c{"slivers_and_guard_band",
           "Sub-pixel slivers, a triangle with vertices far outside the"
           " framebuffer, and a triangle whose vertices collapse when snapped.",
           20, 12, counting()};
    c.commands.push_back(triangles({{0.25f, 0.5f, 0.5f},
                                    {19.75f, 0.6015625f, 0.5f},
                                    {0.25f, 0.50390625f, 0.5f},
                                    {-3000.0f, -2000.0f, 0.0f},
                                    {5000.0f, 6.5f, 1.0f},
                                    {-3000.0f, 9.5f, 0.5f},
                                    {3.0f, 3.0f, 0.5f},
                                    {3.001f, 3.0f, 0.5f},
                                    {3.0f, 9.0f, 0.5f}},
                                   {0, 1, 2, 3, 4, 5, 6, 7, 8}));
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: recode-make-golden OUT_DIR\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  try {
    std::filesystem::create_directories(dir);
    for (Case& c : cases()) {
      CpuDevice dev(c.width, c.height);
      replay(c.commands, dev);
      GoldenVector g;
      g.description = c.description;
      g.stream = {c.width, c.height, std::move(c.commands)};
      const auto depth = dev.depthBuffer();
      const auto stencil = dev.stencilBuffer();
      g.depth.assign(depth.begin(), depth.end());
      g.stencil.assign(stencil.begin(), stencil.end());
      writeGolden(dir / (c.name + ".json"), g);
      std::cout << (dir / (c.name + ".json")).string() << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << "recode-make-golden: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
