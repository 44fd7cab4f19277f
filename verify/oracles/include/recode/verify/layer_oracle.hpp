#pragma once
// The CGAL judge of the layered pair (docs/verification.md, "The layered pair against CGAL"):
// per pixel, the crossings of the pixel-centre line with both snapped meshes in exact
// arithmetic; per pair, CGAL's exact verdict and the volume of the intersection. No CGAL type
// appears here; CGAL lives in cgal_layer_oracle.cpp.

#include <array>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/layered_pair.hpp"

namespace recode::verify {

// Two crossings of one pixel-centre line closer than this many depth steps may be ordered, or
// found equal, either way by the device: each is quantised to the nearest step (half a step
// each), and the contract's double evaluation of the plane adds far less than a step.
inline constexpr double kLayerTieSteps = 2.0;

// The layered pair's interfering pixels against exact crossings.
struct LayerPixelJudgement {
  long long pixels = 0;     // MOR pixels judged
  long long agreed = 0;     // the device's answer is the exact one
  long long ties = 0;       // the answers differ where two crossings lie within kLayerTieSteps
  long long disagreed = 0;  // the answers differ with no tie: a defect of the device or the judge
  long long exactInterfering = 0;                      // pixels where the exact interiors meet
  std::vector<std::array<int, 2>> firstDisagreements;  // up to 16 pixels (x, y)
};

// Judges `result` (collideLayered's on a and b in `frame`, with keepPixels) pixel by pixel: at
// every MOR pixel, the exact depth where the pixel-centre line crosses each triangle that covers
// the centre under the contract's fill rule (docs/rasterization.md sections 2-5: the same snapped
// vertices, the plane through them taken exactly, rational arithmetic), entries and exits paired
// in sorted order, the depths inside each mesh intersected. The fill rule, not a re-cast ray,
// decides a line through an edge or a vertex. Throws std::invalid_argument when the result kept
// no pixels.
[[nodiscard]] LayerPixelJudgement judgeLayeredPixels(const core::TriangleMesh& a,
                                                     const core::TriangleMesh& b,
                                                     const core::FrameSpec& frame,
                                                     const core::LayeredPairResult& result);

// CGAL's exact verdict on two closed meshes as given (double coordinates taken exactly): their
// surfaces meet, or one lies inside the other (Polygon_mesh_processing::do_intersect with the
// bounded-sides test). Throws core::MeshError when a mesh is not a closed manifold surface.
[[nodiscard]] bool closedMeshesMeet(const core::TriangleMesh& a, const core::TriangleMesh& b);

// Whether the two surfaces meet (do_intersect without the bounded-sides test): what a test of
// surfaces alone, such as FCL's mesh-mesh test, answers; a mesh wholly inside another is apart
// for it. Throws as closedMeshesMeet.
[[nodiscard]] bool closedSurfacesMeet(const core::TriangleMesh& a, const core::TriangleMesh& b);

// The volume of the intersection of two closed, outward, self-intersection-free meshes,
// computed by CGAL's corefinement in exact arithmetic and rounded to double (0 when they do not
// overlap). Throws core::MeshError when a mesh is not such a surface, std::runtime_error when the
// corefinement fails.
[[nodiscard]] double closedMeshesOverlapVolume(const core::TriangleMesh& a,
                                               const core::TriangleMesh& b);

}  // namespace recode::verify
