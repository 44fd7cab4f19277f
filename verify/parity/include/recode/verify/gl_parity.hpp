#pragma once
// CPU/GL parity: one command stream replayed on the reference (raster::CpuDevice) and on real
// OpenGL (backends::GlDevice, Mesa llvmpipe), the depth and stencil compared after every command
// that changes them. Coverage must agree bit for bit. llvmpipe interpolates depth in single
// precision from the framebuffer origin, so its depth may differ from the contract's by a
// couple of LSB on ordinary planes and by more on steep or sliver triangles far from the
// origin; each fragment gets a tolerance from a float error bound of that arithmetic (never
// below depthTolerance). A stencil difference is accepted only at a pixel where a depth test
// was decided within that tolerance, and a depth difference only within what the tolerances of
// the fragments there allow. Details: docs/verification.md (the GL parity section).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "recode/backends/gl_platform.hpp"
#include "recode/geometry/mesh.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/device.hpp"

namespace recode::verify {

// The smallest per-fragment depth tolerance, in 24-bit LSB: what the golden vectors showed on
// Mesa 22.3.6 llvmpipe (1 or 2 LSB, never more; docs/rasterization.md section 5).
inline constexpr std::uint32_t kGlDepthTolerance = 2;

struct GlParityCounts {
  long long pixels = 0;       // pixel comparisons: region pixels x read-backs compared
  long long identical = 0;    // depth and stencil equal
  long long depthTies = 0;    // explained by depth rounding (see GlParityReport)
  long long unexplained = 0;  // anything else

  GlParityCounts& operator+=(const GlParityCounts& o) {
    pixels += o.pixels;
    identical += o.identical;
    depthTies += o.depthTies;
    unexplained += o.unexplained;
    return *this;
  }
};

// One pixel that differs without explanation, with both devices' values.
struct GlDifference {
  int command = 0;  // index in the stream of the command after which it was seen
  int x = 0;        // GL window coordinates (y up)
  int y = 0;
  std::uint8_t referenceStencil = 0;
  std::uint8_t candidateStencil = 0;
  std::uint32_t referenceDepth = 0;
  std::uint32_t candidateDepth = 0;
};

struct GlParityReport {
  GlParityCounts counts;
  // Of counts.depthTies: equal stencil, depth apart by more than depthTolerance but within the
  // tolerance of the fragment that wrote it (steep or sliver planes).
  long long wideDepthTies = 0;
  // Of counts.depthTies: the stencil differs, at a pixel where a depth test was decided within
  // the tolerance (so it may have gone either way on GL); the depth is still within bounds.
  long long stencilTies = 0;
  // Largest depth difference among ties with equal stencil, and the largest ratio of such a
  // difference to the tolerance of the fragment that wrote it (how close llvmpipe came to the
  // bound; pixels whose last write was a near decision are left out).
  std::uint32_t maxDepthDifference = 0;
  double maxToleranceFraction = 0.0;
  int comparisons = 0;                 // read-backs compared (initial state, draws, clears)
  std::vector<GlDifference> examples;  // the first few unexplained differences
  std::string renderer;  // the candidate's GL_RENDERER when it is a backends::GlDevice

  [[nodiscard]] bool ok() const { return counts.unexplained == 0; }
};

struct GlParityOptions {
  // Pixels compared (clamped to the framebuffer); the whole framebuffer when not given.
  std::optional<raster::PixelRect> region;
  std::uint32_t depthTolerance = kGlDepthTolerance;  // floor of every fragment's tolerance
  // Widen each fragment's tolerance by the float error bound of llvmpipe's depth plane; off,
  // every fragment is held to depthTolerance alone.
  bool planeErrorBound = true;
  int maxExamples = 8;
  // Where the fixed-function device's context comes from (backends::GlDevice): OSMesa, EGL, or
  // auto (OSMesa when built, else EGL).
  backends::GlPlatform platform = backends::GlPlatform::Auto;
};

// Replays `stream` on `reference` and `candidate` (both fresh: depth 1, stencil 0, default
// state, the stream's size) and compares the region after every draw and clear. The
// near-decision analysis re-evaluates each draw's fragments with the contract's rules
// (raster/triangle_setup.hpp), starting from the reference's read-back before the draw.
// Throws std::invalid_argument for a device whose size is not the stream's; errors of the
// stream itself (a bad draw) propagate from the devices.
[[nodiscard]] GlParityReport compareStreamOnDevices(const raster::CommandStream& stream,
                                                    raster::DepthStencilDevice& reference,
                                                    raster::DepthStencilDevice& candidate,
                                                    const GlParityOptions& options = {});

// The same with a fresh raster::CpuDevice as reference and a fresh backends::GlDevice as candidate.
[[nodiscard]] GlParityReport compareStreamOnGl(const raster::CommandStream& stream,
                                               const GlParityOptions& options = {});

// Runs core::collidePair for A and B on a CpuDevice, records its command stream and compares
// it on GL over the pair's MOR (options.region is replaced by it). The returned report covers
// every step of the algorithm; a pair whose boxes do not overlap draws nothing and compares
// no pixels.
[[nodiscard]] GlParityReport compareOnGl(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                         const core::PairRequest& request,
                                         const GlParityOptions& options = {});

}  // namespace recode::verify
