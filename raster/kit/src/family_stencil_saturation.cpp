// Stencil saturation and wrapping: regions cleared to 254/255 and 0/1, then overlapping
// triangles of both windings with INCR on front faces and DECR on back faces (which saturate
// at 255 and 0), then INCR_WRAP and DECR_WRAP (which wrap).
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

void addTriangle(Rng& rng, int w, int h, cmd::Draw& d) {
  const auto base = static_cast<std::uint32_t>(d.vertices.size());
  for (int k = 0; k < 3; ++k) {
    d.vertices.push_back(fixedVertex(rng.uniform(-256, 256LL * w + 256),
                                     rng.uniform(-256, 256LL * h + 256), rng.depth()));
  }
  d.indices.insert(d.indices.end(), {base, base + 1, base + 2});
}

}  // namespace

Candidate stencilSaturation(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::IncrWraps, Variant::DecrWraps};
  Candidate c;
  c.width = 12;
  c.height = 12;
  c.targets = {kTargets[index % 2]};
  c.description =
      "Stencil cleared to 254/255 on the left and 0/1 on the right, then overlapping triangles "
      "with INCR on front faces and DECR on back faces (saturating at 255 and 0), then "
      "INCR_WRAP and DECR_WRAP (wrapping).";
  const int half = c.width / 2;
  c.commands = {cmd::Scissor{{0, 0, half, c.height}},
                cmd::ClearStencil{static_cast<std::uint8_t>(rng.uniform(254, 255))},
                cmd::Scissor{{half, 0, c.width, c.height}},
                cmd::ClearStencil{static_cast<std::uint8_t>(rng.uniform(0, 1))},
                cmd::Scissor{{0, 0, c.width, c.height}},
                cmd::DepthFunc{CompareFunc::Always},
                opsFor(Face::Front, StencilOp::Keep, StencilOp::Keep, StencilOp::Incr),
                opsFor(Face::Back, StencilOp::Keep, StencilOp::Keep, StencilOp::Decr)};
  for (int pass = 0; pass < 2; ++pass) {
    cmd::Draw d;
    const long long n = rng.uniform(2, 4);
    for (long long k = 0; k < n; ++k)
      addTriangle(rng, c.width, c.height, d);
    c.commands.push_back(std::move(d));
  }
  c.commands.push_back(opsFor(Face::Front, StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap));
  c.commands.push_back(opsFor(Face::Back, StencilOp::Keep, StencilOp::Keep, StencilOp::DecrWrap));
  cmd::Draw d;
  addTriangle(rng, c.width, c.height, d);
  addTriangle(rng, c.width, c.height, d);
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
