#pragma once
// The modes' promises on generated inputs nobody wrote by hand (docs/accuracy.md, "What each
// mode promises"): pairs at and near contact, of thin posts, flat disks, large spheres on small
// features, boxes face to face and edge to edge, capsules and cone tips, each block turned by
// 1e-9 to 10 degrees about an axis through the contact, drawn at 128 to 1024 pixels along any
// world axis, and judged by CGAL on the blocks as drawn. The promises:
//   - the conservative mode misses no pair CGAL says intersect, and says collide wherever the
//     reference does;
//   - the adaptive mode says a definite `apart` for no pair CGAL says intersect;
//   - the reference mode invents no contact beyond a touch within depth rounding (an extra the
//     CGAL judgement explains, verify::judgePair);
//   - every conservative extra lies within its bound (A grown by twice the growth meets B).

#include <cstdint>
#include <string>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/refine/adaptive.hpp"
#include "recode/verify/mode_check.hpp"

namespace recode::verify {

struct PropertyCase {
  std::string label;     // e.g. "sphere-on-post/000012 A 3.2e-06 deg about x, gap -1.0e-04, z 256"
  core::TriangleMesh a;  // world coordinates
  core::TriangleMesh b;
  core::FrameSpec frame;
};

// Case `index` (>= 0) of the suite for `seed`: the same case on every compiler and library.
// Six configurations take turns; every draw comes from one std::mt19937 seeded by seed and index.
[[nodiscard]] PropertyCase propertyCase(long long index, std::uint32_t seed = 20261126);

// The promises counted over cases. holds() when none is broken.
struct PropertyTally {
  long long cases = 0;
  long long intersect = 0;                      // CGAL
  long long conservativeMissed = 0;             // CGAL intersect, conservative apart
  long long conservativeBelowReference = 0;     // reference collide, conservative apart
  long long adaptiveFalseApart = 0;             // CGAL intersect, adaptive definite apart
  long long referenceExtras = 0;                // reference collide, CGAL apart ...
  long long referenceExtrasUnexplained = 0;     // ... not a touch within depth rounding
  long long conservativeExtras = 0;             // conservative collide, CGAL apart ...
  long long conservativeExtrasBeyondBound = 0;  // ... beyond the bound
  long long adaptiveApartAtLimit = 0;           // neither a miss nor a promise broken
  long long referenceMissed = 0;                // resolution misses: allowed, counted
  std::vector<std::string> failures;            // the first 20 broken cases and what broke

  [[nodiscard]] bool holds() const {
    return conservativeMissed == 0 && conservativeBelowReference == 0 && adaptiveFalseApart == 0 &&
           referenceExtrasUnexplained == 0 && conservativeExtrasBeyondBound == 0;
  }
};

// Runs cases first .. first + count - 1 through the three modes (verify::checkModes, CpuDevice)
// and CGAL, adding each to the tally. Needs CGAL (std::runtime_error otherwise).
void checkModeProperties(long long first, long long count, std::uint32_t seed,
                         core::AdaptivePairTester& tester, PropertyTally& tally);

}  // namespace recode::verify
