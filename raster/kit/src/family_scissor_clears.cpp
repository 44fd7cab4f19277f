// Scissors and clears: scissor rectangles partly outside the frame, empty or inverted, with
// depth clears (some while the depth write mask is off, which must change nothing) and stencil
// clears through write masks, and triangles drawn inside them.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

PixelRect randomRect(Rng& rng, int w, int h) {
  const auto coord = [&rng](int size) { return static_cast<int>(rng.uniform(-4, size + 4)); };
  PixelRect r{coord(w), coord(h), coord(w), coord(h)};
  if (!rng.chance(15)) {  // usually ordered; sometimes inverted (empty)
    if (r.x0 > r.x1)
      std::swap(r.x0, r.x1);
    if (r.y0 > r.y1)
      std::swap(r.y0, r.y1);
  }
  return r;
}

double clearValue(Rng& rng) {
  return static_cast<double>(rng.uniform(0, 1 << 20)) / static_cast<double>(1 << 20);
}

}  // namespace

Candidate scissorClears(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::ClearIgnoresScissor,
                                     Variant::StencilClearIgnoresWriteMask,
                                     Variant::DepthClearIgnoresWriteMask};
  Candidate c;
  c.width = 16;
  c.height = 16;
  c.targets = {kTargets[index % 3]};
  c.description =
      "Scissors partly outside the frame, empty or inverted; depth clears (some with the depth "
      "write mask off: no change), stencil clears through write masks, and triangles drawn "
      "inside the scissor counting +1/-1.";
  c.commands = countFacingsKeepDepth();
  const long long steps = rng.uniform(3, 6);
  for (long long s = 0; s < steps; ++s) {
    c.commands.push_back(cmd::Scissor{randomRect(rng, c.width, c.height)});
    switch (rng.uniform(0, 2)) {
      case 0: {
        const bool write = rng.chance(50);
        c.commands.push_back(cmd::DepthWriteMask{write});
        c.commands.push_back(cmd::ClearDepth{clearValue(rng)});
        c.commands.push_back(cmd::DepthWriteMask{true});
        break;
      }
      case 1:
        c.commands.push_back(cmd::StencilWriteMask{static_cast<std::uint8_t>(rng.uniform(0, 255))});
        c.commands.push_back(cmd::ClearStencil{static_cast<std::uint8_t>(rng.uniform(0, 255))});
        c.commands.push_back(cmd::StencilWriteMask{0xFF});
        break;
      default: {
        cmd::Draw d;
        for (int k = 0; k < 3; ++k) {
          d.vertices.push_back(fixedVertex(rng.uniform(-256, 256LL * 17),
                                           rng.uniform(-256, 256LL * 17), rng.depth()));
        }
        d.indices = {0, 1, 2};
        c.commands.push_back(std::move(d));
        break;
      }
    }
  }
  return c;
}

}  // namespace recode::kit::detail
