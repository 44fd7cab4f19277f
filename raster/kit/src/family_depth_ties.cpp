// Depth ties: depths whose product z * 16777215, rounded to double, is exactly k + 0.5 with k
// even, where round half to even gives k and rounding half up k + 1. Two sources:
//   - a depth clear of a double d chosen so that d * 16777215 rounds to k + 0.5;
//   - a plane whose exact z * 16777215 is a half-integer at every sample (tiePlane,
//     family_tie_plane.cpp); the double arithmetic lands on it at many columns (the generator
//     keeps only candidates where it does at one with k even).
#include <cmath>

#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

// A double d with d * 16777215 == k + 0.5 exactly after rounding, k even.
double tieClearValue(Rng& rng) {
  for (;;) {
    const double k = static_cast<double>(2 * rng.uniform(1, 8388606));
    const double d = (k + 0.5) / 16777215.0;
    for (const double candidate : {d, std::nextafter(d, 0.0), std::nextafter(d, 1.0)}) {
      if (candidate * 16777215.0 == k + 0.5)
        return candidate;
    }
  }
}

}  // namespace

Candidate depthTies(Rng& rng, int index) {
  Candidate c;
  c.width = static_cast<int>(rng.uniform(8, 24));
  c.height = 2;
  c.targets = {Variant::QuantiseHalfUp};
  // Even indices: the plane alone must show a tie. Odd ones: a tied clear on the left half too.
  const bool clear = index % 2 == 1;
  const int drawFrom = clear ? c.width / 2 : 0;
  if (clear) {
    c.commands = {cmd::Scissor{{0, 0, drawFrom, c.height}}, cmd::ClearDepth{tieClearValue(rng)}};
  }
  c.commands.push_back(cmd::Scissor{{drawFrom, 0, c.width, c.height}});
  c.commands.push_back(cmd::DepthFunc{CompareFunc::Always});
  c.commands.push_back(cmd::StencilFunc{CompareFunc::Always, 0, 0xFF});
  c.commands.push_back(opsFor(Face::Both, StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap));
  c.description = std::string(clear ? "Depth ties: the left half is cleared to a depth d with "
                                      "d * 16777215 = k + 0.5 (k even), the right half"
                                    : "Depth ties: the frame is") +
                  " drawn with a plane whose z * 16777215 is k + 0.5 with k even at some "
                  "columns: round half to even keeps k, rounding half up gives k + 1.";
  c.commands.push_back(tiePlane(rng, c.width, c.height, false, rng.chance(50)));
  c.commands.push_back(cmd::Scissor{{0, 0, c.width, c.height}});
  return c;
}

}  // namespace recode::kit::detail
