#pragma once
// The layered pair (docs/algorithm.md, "Closed meshes: the layered pair"): RECODE's counting
// generalised from convex blocks to any two closed, consistently and outwardly oriented
// triangle meshes. Along the view ray through a pixel centre a closed mesh is entered at each
// of its front-facing fragments and left at each back-facing one; the stencil counts them, then
// one pass per layer captures each pixel's k-th front (or back) fragment in the order the
// contract draws them, and a sweep over the sorted depths gives the depth intervals inside both
// meshes. Only the contract's operations are used (raster/device.hpp), so every exact device
// gives the same bytes.
//
// The pair test follows the request -> result shape of collidePair and shares its PairRequest:
// the frame, the MOR, the box test and keepPixels mean what they mean there; `contact` and
// `normal` ask for the contact points and the normal.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "recode/pair/pair.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/pixel_buffer.hpp"

namespace recode::core {

// The most fragments of one facing (entries, or exits) a closed mesh may have at a pixel: the
// stencil counts them in 8 bits and saturates at 255, so a count of 255 cannot be told from
// more and is refused.
inline constexpr int kMaxLayers = 254;

// The steps of the layered pair, in order, for timing.
enum class LayerStep {
  Count,    // four passes: each mesh's front and back fragments counted in the stencil, read
  Capture,  // one pass per layer, facing and mesh: the k-th fragment's depth captured, read
  Sweep,    // the host's sweep over every pixel's sorted depths
};
inline constexpr int kLayerStepCount = 3;
[[nodiscard]] std::string_view toString(LayerStep step);  // "count", "capture", "sweep"

// Wall-clock time of one collideLayered call, microseconds.
struct LayeredTiming {
  std::array<double, kLayerStepCount> stepUs{};  // indexed by LayerStep
  double totalUs = 0.0;
};

// One pixel as the sweep saw it (`recode pair --pixel` on a closed-mesh pair; teaching): each
// mesh's entries (front-facing fragments) and exits (back-facing ones) in depth order, the
// intervals inside each mesh that the sweep pairs them into (DepthInterval: pair_cases.hpp),
// and those inside both. Empty
// lists where the mesh has no fragment at the pixel; all empty when the pixel lies outside the
// MOR or nothing was drawn (inMor false).
struct LayeredPixel {
  int x = 0;
  int y = 0;
  bool inMor = false;
  std::vector<std::uint32_t> entriesA, exitsA, entriesB, exitsB;
  std::vector<DepthInterval> insideA, insideB, insideBoth;
};

// Which mesh, if either, lies wholly inside the other (section "Containment" of the doc).
enum class Containment { None, AInsideB, BInsideA, Same };
[[nodiscard]] std::string_view toString(Containment c);  // "none", "a_inside_b", ...

// Everything collideLayered found for a pair.
struct LayeredPairResult {
  bool collide = false;       // some pixel's depth intervals inside A and inside B meet
  bool boxesOverlap = false;  // false with the box test on: nothing was drawn
  raster::PixelRect mor;      // the rectangle the passes ran over (empty if none)
  long long interferingPixels = 0;
  // Per MOR pixel (rect == mor; kept with PairRequest::keepPixels): the total length of the
  // depth intervals inside both meshes, in depth steps, and whether the pixel interferes (a
  // pixel whose intervals only touch interferes with length 0).
  raster::PixelBuffer<std::uint32_t> overlapSteps;
  raster::PixelBuffer<std::uint8_t> interferes;
  raster::PixelRect contactRect;  // bounding rectangle of the interfering pixels
  // points: one per overlap interval, at its middle (with `contact`); box: both ends of every
  // overlap interval; pixels and area: the interfering pixels; maxDepth: the longest single
  // overlap interval; collapsedPixels: pixels where some mesh's entry lay beyond its paired
  // exit by rounding (its interval is then taken between the two); normal: with `normal`.
  ContactRegion contact;
  // The sum over the MOR of each pixel's overlap length times the pixel's area, world units
  // cubed: an estimate of the volume of A ∩ B (docs/accuracy.md gives its error).
  double overlapVolume = 0.0;
  Containment containment = Containment::None;
  int layersA = 0;  // the most entries of A at one MOR pixel
  int layersB = 0;  // the same for B
  int passes = 0;   // depth/stencil passes drawn (count and capture)
  long long stencilPixelsRead = 0;
  long long depthPixelsRead = 0;
  double depthMin = 0.0;  // the world range along the view axis mapped onto depth [1, 0]
  double depthMax = 0.0;
  LayeredTiming timing;
  std::optional<LayeredPixel> pixel;  // the probed pixel, when one was asked for
};

// The layered pair test of two closed meshes (world coordinates) on `device`, whose size must be
// request.frame's. The meshes must be closed and outwardly oriented (geometry's closed-mesh
// checks); what the passes can see of a mesh that is not is refused: a pixel whose front and
// back fragment counts differ throws std::invalid_argument naming the pixel, and so does one
// with more than kMaxLayers fragments of one facing. Throws as collidePair does for a size
// mismatch or a vertex the view cannot map.
[[nodiscard]] LayeredPairResult collideLayered(raster::DepthStencilDevice& device,
                                               const PairBlock& a, const PairBlock& b,
                                               const PairRequest& request);
[[nodiscard]] LayeredPairResult collideLayered(raster::DepthStencilDevice& device,
                                               const TriangleMesh& a, const TriangleMesh& b,
                                               const PairRequest& request);
// The same, also keeping the sweep's view of pixel (x, y) of the frame in result.pixel; the rest
// of the result is the same bytes.
[[nodiscard]] LayeredPairResult collideLayered(raster::DepthStencilDevice& device,
                                               const PairBlock& a, const PairBlock& b,
                                               const PairRequest& request,
                                               std::array<int, 2> probePixel);

}  // namespace recode::core
