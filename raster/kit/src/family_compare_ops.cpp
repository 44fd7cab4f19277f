// Compare functions x stencil ops x faces: vector i takes stencil compare function i % 8 and
// face (i / 8) % 3; eight quads each set that face's ops to a rotation of the eight ops, so
// every op appears in every slot (sfail, dpfail, dppass). Each quad is one counter-clockwise
// and one clockwise triangle, over columns of stored stencil values around ref and at 0 and
// 255, and rows of stored depth that the quad's depth passes (LESS) and fails.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

Candidate compareOps(Rng& rng, int index) {
  const auto func = static_cast<CompareFunc>(index % 8);
  const auto face = static_cast<Face>((index / 8) % 3);
  Candidate c;
  c.width = 32;
  c.height = 8;
  c.targets = {Variant::SwappedFacing, Variant::IgnoreValueMask, Variant::IncrWraps,
               Variant::DecrWraps};
  const auto ref = static_cast<std::uint8_t>(rng.uniform(1, 254));
  const auto valueMask = static_cast<std::uint8_t>(rng.chance(50) ? 255 : rng.uniform(1, 254));
  c.description = "Stencil func " + std::string(toString(func)) + " (ref " + std::to_string(ref) +
                  ", value mask " + std::to_string(valueMask) + "), ops set for face " +
                  std::string(toString(face)) +
                  ": eight quads, each op in each slot, one counter-clockwise and one clockwise "
                  "triangle per quad, over stored stencil 0, ref - 1, ref, ref + 1, 255 and "
                  "stored depth that the fragments pass and fail.";
  // Stored stencil by column within each quad, stored depth by row.
  const std::uint8_t stored[4] = {static_cast<std::uint8_t>(rng.chance(50) ? 0 : 255),
                                  static_cast<std::uint8_t>(ref - 1), ref,
                                  static_cast<std::uint8_t>(ref + 1)};
  for (int col = 0; col < 4; ++col) {
    for (int q = 0; q < 8; ++q) {
      c.commands.push_back(cmd::Scissor{{4 * q + col, 0, 4 * q + col + 1, c.height}});
      c.commands.push_back(cmd::ClearStencil{q % 2 == 0 ? stored[col] : stored[3 - col]});
    }
  }
  c.commands.push_back(cmd::Scissor{{0, 0, c.width, c.height / 2}});
  c.commands.push_back(cmd::ClearDepth{0.25});
  c.commands.push_back(cmd::Scissor{{0, 0, c.width, c.height}});
  c.commands.push_back(cmd::StencilFunc{func, ref, valueMask});
  for (int q = 0; q < 8; ++q) {
    c.commands.push_back(opsFor(face, static_cast<StencilOp>(q),
                                static_cast<StencilOp>((q + 3) % 8),
                                static_cast<StencilOp>((q + 5) % 8)));
    // The quad [4q, 4q + 4] x [0, 8] at depth 0.5, split along a diagonal: the lower triangle
    // counter-clockwise, the upper one clockwise.
    const long long x0 = 256 * 4 * q, x1 = x0 + 256 * 4, y1 = 256 * 8;
    cmd::Draw d;
    d.vertices = {fixedVertex(x0, 0, 0.5f), fixedVertex(x1, 0, 0.5f), fixedVertex(x1, y1, 0.5f),
                  fixedVertex(x0, y1, 0.5f)};
    d.indices = {0, 1, 2, 0, 3, 2};
    if (q % 2 == 1)
      d.indices = {0, 1, 3, 1, 3, 2};  // the other diagonal
    c.commands.push_back(std::move(d));
  }
  return c;
}

}  // namespace recode::kit::detail
