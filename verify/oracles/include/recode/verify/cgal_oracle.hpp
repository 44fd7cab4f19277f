#pragma once
// The CGAL oracle: the exact intersection of two closed convex blocks, and the judgement of a
// RECODE pair result against it (docs/verification.md, "The CGAL oracle"). No CGAL type appears
// here; CGAL lives in cgal_oracle.cpp alone, the judgement needs no CGAL at all.

#include <string>
#include <string_view>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"

namespace recode::verify {

// The intersection of the two blocks as given: their double coordinates taken exactly, both
// blocks closed sets (touching at a single point is intersecting).
struct ExactIntersection {
  bool intersect = false;
  // Volume of the intersection solid (0 when the blocks only touch), rounded to double.
  double volume = 0.0;
  // The exact solid's bounding box rounded outward to doubles; empty when !intersect.
  core::Aabb box;
  // Distinct exact points found on the solid's boundary: all its vertices, and possibly
  // points on its edges and faces as well.
  long long boundaryPoints = 0;
};

// Decides with an exact kernel (CGAL Epeck, GMP rationals). Both meshes must be valid convex
// blocks (core::validateConvexBlock; core::MeshError naming "block A" or "block B"
// otherwise). Throws std::logic_error if CGAL's do_intersect and the exact vertex
// construction disagree, which would be a bug in the oracle.
[[nodiscard]] ExactIntersection exactIntersection(const core::TriangleMesh& worldA,
                                                  const core::TriangleMesh& worldB);

// Only exactIntersection's verdict (`intersect`), the same closed-set rules (touching at a point
// counts, so does one block inside the other), without constructing the solid: cheap enough for
// the bench's exact judge to call on every candidate pair of every frame. The same checks and
// errors as exactIntersection.
[[nodiscard]] bool exactlyIntersect(const core::TriangleMesh& worldA,
                                    const core::TriangleMesh& worldB);

// Whether A grown by the box of half-sides `half` (the Minkowski sum A + [-h, h]^3 per axis)
// meets B, decided exactly: the grown block is CGAL's hull of every vertex of A plus every corner
// of the box, the sums taken exactly, so no block the program made is ever rounded or checked as
// input. A and B are the user's blocks and are validated as exactlyIntersect validates them.
// What `recode verify --modes` uses to check a conservative extra's bound.
[[nodiscard]] bool grownBlockMeets(const core::TriangleMesh& worldA, const Eigen::Vector3d& half,
                                   const core::TriangleMesh& worldB);

// The tolerances of the judgement, in the units of the device (docs/verification.md).
// An overlap or gap along the view axis within this many depth steps (LSB of 24-bit depth over
// the pair's depth range) is within rounding: each end of a depth interval is off by at most
// 1 LSB (1/2 from rounding the vertex depth to float, 1/2 from quantisation), so an overlap by
// at most 2; the third absorbs the plane evaluation's rounding.
inline constexpr double kDepthToleranceLsb = 3.0;
// A pixel centre this close to a block's silhouette (in pixels, each image-plane direction) may
// fall either side of it on the device: snapping vertices to the 1/256-pixel grid moves them by
// at most 1/512 pixel in x and in y.
inline constexpr double kEdgeTolerancePixels = 1.0 / 256.0;

enum class VerdictCheck {
  Agree,           // same verdict (and, when both collide, the contact box fits)
  ResolutionMiss,  // CGAL intersect, RECODE apart: no pixel could see the overlap (judgePair)
  RoundingExtra,   // CGAL apart, RECODE collide: a touch within the device's rounding (judgePair)
  Disagree,        // anything else: a bug in RECODE or in the oracle
};
[[nodiscard]] std::string_view toString(
    VerdictCheck check);  // "agree", "resolution miss", "extra within rounding", ...

struct CgalJudgement {
  VerdictCheck verdict = VerdictCheck::Agree;
  std::string reason;  // one sentence with the numbers the verdict rests on
  bool exactIntersect = false;
  bool recodeCollide = false;
  // RECODE's contact box lies within the exact box widened by one pixel on the image plane and
  // by the depth tolerance along the view axis. Only checked when both say collide; true
  // otherwise.
  bool contactBoxInside = true;
  // Inside, or reaching beyond only where the blocks touch within rounding (see judgePair);
  // false makes the verdict Disagree.
  bool contactBoxExplained = true;
  // Interfering pixels outside the widened exact box where the blocks touch within rounding.
  long long touchingPixelsOutside = 0;
  // The pixel the verdict rests on (the thickest overlap or the widest gap), -1 if none.
  int pixelX = -1;
  int pixelY = -1;
  double depthStep = 0.0;       // one depth LSB in world units for this pair
  double depthTolerance = 0.0;  // kDepthToleranceLsb depth steps, world units
};

// Compares RECODE's result for the pair (worldA, worldB) rendered in `frame` with the exact
// answer. Different verdicts are a ResolutionMiss (a) or a RoundingExtra (b) when
//  (a) CGAL says intersect, RECODE says apart, and no pixel can be shown to have needed to see
//      the overlap: a pixel must see it when, at all four corners of the square of half-size
//      kEdgeTolerancePixels around its centre, the view lines meet both blocks and the overlap
//      of the blocks' intervals, taken as the smallest far end minus the largest near end over
//      the four corners, exceeds the depth tolerance (by convexity that bounds what the device
//      can draw anywhere in the square);
//  (b) CGAL says apart, RECODE says collide, and every interfering pixel is explained: within
//      the square around its centre both blocks are present and the depth ranges they occupy
//      there come within the depth tolerance of each other.
// Anything else is Disagree. When both collide, the contact box must lie within the exact box
// widened by one pixel on the image plane and the depth tolerance along the axis; where it
// reaches beyond, it must be explained by interfering pixels at which the blocks touch within
// rounding (rule (b)'s test): each such pixel allows its +-1/256 px square and the depth range
// between the blocks there, widened by the tolerance. Faces touching over a wide area within
// rounding have an exact intersection that is a sliver (or a face) while the device sees the whole
// contact. An unexplained contact box is Disagree. Throws std::invalid_argument when the result's
// depth range or the frame is unusable.
[[nodiscard]] CgalJudgement judgePair(const ExactIntersection& exact, const core::FrameSpec& frame,
                                      const core::TriangleMesh& worldA,
                                      const core::TriangleMesh& worldB,
                                      const core::PairResult& result);

// The exact intersection solid of the two blocks (its convex hull, built exactly), its
// vertices rounded to doubles, for the contact normal oracle (contact_normal_oracle.hpp). Empty
// when the blocks are apart or their intersection has no volume. The same checks and errors as
// exactIntersection.
[[nodiscard]] core::TriangleMesh intersectionHull(const core::TriangleMesh& worldA,
                                                  const core::TriangleMesh& worldB);

struct CgalCounts {
  long long pairs = 0;
  long long agree = 0;
  long long resolutionMisses = 0;  // RECODE apart where CGAL intersects, explained
  long long roundingExtras = 0;    // RECODE collide where CGAL is apart, explained
  long long disagree = 0;

  void add(const CgalJudgement& judgement);
};

}  // namespace recode::verify
