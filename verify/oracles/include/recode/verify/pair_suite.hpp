#pragma once
// A deterministic suite of convex block pairs for the oracles: mixed shapes in random poses,
// plus the configurations where image-space collision detection is hardest on purpose (tips
// meeting tips and faces, faces on faces, crossing edges, one block inside the other, blocks a
// hair apart). The same options always give the same pairs, bit for bit, on any machine.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"

namespace recode::verify {

enum class PairConfiguration {
  Random,         // two random shapes in random poses, overlapping or not
  TipOnTip,       // two pointed blocks (cones, needles) whose apexes meet
  TipOnFace,      // an apex pressed onto / held just off a face of a box or octahedron
  FaceOnFace,     // two boxes with parallel faces touching, overlapping or a hair apart
  EdgeOnEdge,     // two boxes whose edges cross
  Inside,         // a small block entirely inside a larger one
  JustSeparated,  // a random pair moved apart along a direction until just separated
};
inline constexpr int kPairConfigurationCount = 7;

[[nodiscard]] std::string_view toString(PairConfiguration configuration);

struct SuitePair {
  std::string label;  // unique within a suite, e.g. "tip-on-tip/012 cone-needle z"
  PairConfiguration configuration = PairConfiguration::Random;
  core::TriangleMesh a;  // world coordinates
  core::TriangleMesh b;
  core::FrameSpec frame;  // core::resolveFrame's defaults over both blocks, at the suite's width
};

struct PairSuiteOptions {
  int count = 504;                // pairs in all, spread evenly over the configurations
  std::uint32_t seed = 20261122;  // std::mt19937 seed
  int width = 64;                 // frame width in pixels; the height keeps pixels square
};

// Generates the suite. Throws std::invalid_argument for count < 1 or width outside 1..4096.
[[nodiscard]] std::vector<SuitePair> generatePairSuite(const PairSuiteOptions& options = {});

}  // namespace recode::verify
