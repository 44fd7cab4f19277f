#pragma once
// RECODE for one pair of convex blocks (docs/algorithm.md): the MOR,
// the depth/stencil passes, the per-pixel cases 0-8 and the contact region, all through
// raster::DepthStencilDevice so any back end can replay the command stream. Queries follow
// a request -> result shape.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/contact_normal.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/pixel_buffer.hpp"

namespace recode::core {

// Which pixel rectangle the passes run over and the stencil is read from (the paper's
// Table 1): Min = the projection of AABB(A) intersected with AABB(B); Max = the bounding
// rectangle of both projected boxes; Full = the whole frame.
enum class MorMode { Min, Max, Full };

[[nodiscard]] std::string_view toString(MorMode mode);                     // "min", "max", "full"
[[nodiscard]] std::optional<MorMode> parseMorMode(std::string_view name);  // nullopt if unknown

// What collidePair draws and measures.
struct PairRequest {
  FrameSpec frame;             // the frame; the device must be of its size
  MorMode mor = MorMode::Min;  // the rectangle the passes run over
  // Run the two extra depth passes that measure the overlap interval of interfering pixels
  // (contact points, box, greatest depth). Without them only the verdict, the cases, the
  // pixel count and the area are known.
  bool contact = true;
  // Skip the passes when the blocks' boxes (projected footprints and depth ranges of the
  // snapped vertices) cannot interfere. The verdict is the same either way; turning it off
  // shows the cases 1, 2, 7 and 8 of blocks that are apart (teaching, tests).
  bool boxTest = true;
  // Also estimate the contact normal and penetration depth from the contact passes' depths
  // (ContactRegion::normal; docs/algorithm.md). Needs `contact`; off, nothing changes.
  bool normal = false;
  // Keep the pixels: the case map and the contact points (one per interfering pixel). Off,
  // both are left empty and everything else is the same, and a batch (collidePairs) may have
  // a GPU device reduce its buffers to a summary of 64 bytes a pair test instead of reading
  // them back (pair_batch.hpp).
  bool keepPixels = true;
};

// The steps of the algorithm, in order, for timing and for observers (recode explain).
enum class PairStep {
  SetZ,           // RenderSetZ(A, GEQUAL): depth = Amax, stencil 1 under A
  TestZ,          // RenderTestZ(B, LEQUAL): stencil = 1 + faces of B at or before Amax
  LoadAmin,       // depth = Amin (A's faces with LEQUAL)
  TestAminFront,  // bit 2: B's front face at or behind Amin
  TestAminBack,   // bit 3: B's back face at or behind Amin
  ReadStencil,    // stencil over the MOR read back and classified
  ContactNear,    // depth = max(Amin, Bmin) over the interfering pixels' rectangle
  ContactFar,     // depth = min(Amax, Bmax) over the same rectangle
};
inline constexpr int kPairStepCount = 8;  // the number of PairStep values
// The step's name in reports and JSON ("set_z", "test_z", ...).
[[nodiscard]] std::string_view toString(PairStep step);

// Called after each step with the device in its state after that step. An observer may read
// back anything (recode explain does); it must not change device state.
class PairObserver {
 public:
  virtual ~PairObserver() = default;
  // Called once for each step that runs, in order.
  virtual void afterStep(PairStep step, raster::DepthStencilDevice& device) = 0;
};

// Where two blocks overlap, as the interfering pixels measure it.
struct ContactRegion {
  // One point per interfering pixel: the pixel centre, halfway along the overlap interval.
  std::vector<Eigen::Vector3d> points;
  // Box of both ends of every pixel's overlap interval (empty without interference or
  // without the contact passes).
  Aabb box;
  long long pixels = 0;   // interfering pixels
  double area = 0.0;      // pixels * pixel width * pixel height, world units squared
  double maxDepth = 0.0;  // greatest overlap interval length along the view axis, world units
  // Pixels whose measured near end lay one or more steps beyond the far end: the blocks
  // touch there within depth rounding, and the overlap is taken as one depth between the two.
  long long collapsedPixels = 0;
  // With PairRequest::normal and interference: the contact normal (from A towards B) and the
  // penetration depth along it (contact_normal.hpp).
  std::optional<ContactNormal> normal;
};

// Wall-clock time of one collidePair call, microseconds.
struct PairTiming {
  std::array<double, kPairStepCount> stepUs{};  // indexed by PairStep
  double classifyUs = 0.0;                      // decoding the stencil, building the contact
  double totalUs = 0.0;                         // the whole call
};

// Everything collidePair found for a pair.
struct PairResult {
  bool collide = false;       // some pixel is in case 3-6: the blocks interfere
  bool boxesOverlap = false;  // false with the box test on: nothing was drawn
  raster::PixelRect mor;      // the rectangle the passes ran over (empty if none)
  std::array<long long, kCaseCount> caseCounts{};  // pixels of each case inside the MOR
  long long interferingPixels = 0;                 // pixels in cases 3-6
  // Case of every MOR pixel (rect == mor; empty when nothing was drawn).
  raster::PixelBuffer<std::uint8_t> caseMap;
  raster::PixelRect contactRect;    // bounding rectangle of the interfering pixels
  ContactRegion contact;            // the contact region (points and box with the contact passes)
  long long stencilPixelsRead = 0;  // the MOR's area
  long long depthPixelsRead = 0;    // twice the contact rectangle's area (both contact passes)
  double depthMin = 0.0;            // the world range along the view axis mapped onto depth [1, 0]
  double depthMax = 0.0;            // the upper end of that range
  PairTiming timing;                // per step
};

// Runs RECODE for A and B (world coordinates, each a closed convex block) on `device`, whose
// size must equal request.frame's. Throws std::invalid_argument for a size mismatch or a
// vertex the view cannot map (beyond fixed-point range).
[[nodiscard]] PairResult collidePair(raster::DepthStencilDevice& device, const TriangleMesh& a,
                                     const TriangleMesh& b, const PairRequest& request,
                                     PairObserver* observer = nullptr);

// The same for blocks that carry what can be worked out once (pair_block.hpp): with a
// hierarchy, a device that draws only what meets its scissor is handed only the triangles near
// the MOR. The commands and the result are those of the overload above, bit for bit.
[[nodiscard]] PairResult collidePair(raster::DepthStencilDevice& device, const PairBlock& a,
                                     const PairBlock& b, const PairRequest& request,
                                     PairObserver* observer = nullptr);

// The pieces collidePair is made of, for tests and back-end authors.

// The world range along the axis the pair's depth maps onto: the union of both boxes.
[[nodiscard]] std::array<double, 2> pairDepthRange(ViewAxis axis, const Aabb& a, const Aabb& b);

// Pixels whose centres lie in the closed window-space box of the given (snapped) vertices.
[[nodiscard]] raster::PixelRect pixelFootprint(std::span<const raster::WindowVertex> vertices,
                                               int width, int height);

}  // namespace recode::core
