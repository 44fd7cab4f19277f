// Masks with REPLACE: the stencil cleared through a write mask, then a stencil test under a
// value mask and REPLACE (with INVERT and INCR beside it) written through another write mask.
// REPLACE writes ref itself, not ref & value mask; the value mask applies to the test only.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

std::uint8_t byte(Rng& rng) {
  return static_cast<std::uint8_t>(rng.uniform(0, 255));
}

// A mask that is neither 0 nor 0xFF most of the time.
std::uint8_t mask(Rng& rng) {
  return static_cast<std::uint8_t>(rng.chance(85) ? rng.uniform(1, 254) : 255);
}

}  // namespace

Candidate masksReplace(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::IgnoreValueMask,
                                     Variant::StencilClearIgnoresWriteMask};
  Candidate c;
  c.width = 16;
  c.height = 16;
  c.targets = {kTargets[index % 2]};
  c.description =
      "The stencil cleared, then cleared again in a scissor through a write mask; a stencil "
      "test under a value mask with REPLACE (ref itself is written) beside INVERT and INCR, "
      "written through a write mask; depth LESS against a half cleared to 0.5.";
  static const std::vector<StencilOp> kOthers = {StencilOp::Keep, StencilOp::Invert,
                                                 StencilOp::Incr, StencilOp::Zero};
  static const std::vector<CompareFunc> kFuncs = {CompareFunc::Less,     CompareFunc::Equal,
                                                  CompareFunc::LEqual,   CompareFunc::Greater,
                                                  CompareFunc::NotEqual, CompareFunc::GEqual};
  const long long sx = rng.uniform(2, 14), sy = rng.uniform(2, 14);
  c.commands = {cmd::ClearStencil{byte(rng)},
                cmd::StencilWriteMask{mask(rng)},
                cmd::Scissor{{static_cast<int>(sx), 0, c.width, static_cast<int>(sy)}},
                cmd::ClearStencil{byte(rng)},
                cmd::ClearDepth{0.5},
                cmd::Scissor{{0, 0, c.width, c.height}},
                cmd::StencilWriteMask{mask(rng)},
                cmd::StencilFunc{rng.pick(kFuncs), byte(rng), mask(rng)}};
  // REPLACE in one slot, the others from kOthers.
  StencilOp ops[3] = {rng.pick(kOthers), rng.pick(kOthers), rng.pick(kOthers)};
  ops[rng.uniform(0, 2)] = StencilOp::Replace;
  c.commands.push_back(opsFor(Face::Both, ops[0], ops[1], ops[2]));
  cmd::Draw d;
  const long long n = rng.uniform(2, 4);
  for (long long t = 0; t < n; ++t) {
    const auto base = static_cast<std::uint32_t>(d.vertices.size());
    for (int k = 0; k < 3; ++k) {
      d.vertices.push_back(
          fixedVertex(rng.uniform(-512, 256LL * 18), rng.uniform(-512, 256LL * 18), rng.depth()));
    }
    d.indices.insert(d.indices.end(), {base, base + 1, base + 2});
  }
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
