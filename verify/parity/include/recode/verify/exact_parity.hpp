#pragma once
// Bit-exact parity: one command stream replayed on the reference (raster::CpuDevice) and on a
// device that claims the contract exactly (backends::GlExactDevice, backends::VulkanDevice), depth
// and stencil compared after the fresh start and after every draw and clear. No tolerance: a pixel
// is identical or different.

#include <optional>
#include <string>
#include <vector>

#include "recode/backends/gl_platform.hpp"
#include "recode/geometry/mesh.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/device.hpp"
#include "recode/sim/simulation.hpp"
#include "recode/verify/gl_parity.hpp"

namespace recode::verify {

struct ExactParityCounts {
  long long pixels = 0;     // pixel comparisons: region pixels x read-backs compared
  long long identical = 0;  // depth and stencil both equal
  long long different = 0;  // anything else

  ExactParityCounts& operator+=(const ExactParityCounts& o) {
    pixels += o.pixels;
    identical += o.identical;
    different += o.different;
    return *this;
  }
};

struct ExactParityReport {
  ExactParityCounts counts;
  int comparisons = 0;                 // read-backs compared
  std::vector<GlDifference> examples;  // the first few differing pixels, both devices' values
  std::string renderer;                // the candidate's, when the comparison made it

  [[nodiscard]] bool ok() const { return counts.different == 0; }
};

// Replays `stream` on `reference` and `candidate` (both fresh and of the stream's size) and
// compares `region` (clamped to the framebuffer; all of it when not given) after the start and
// after every draw and clear. Throws std::invalid_argument for a device of another size.
[[nodiscard]] ExactParityReport compareStreamExactly(const raster::CommandStream& stream,
                                                     raster::DepthStencilDevice& reference,
                                                     raster::DepthStencilDevice& candidate,
                                                     std::optional<raster::PixelRect> region = {},
                                                     int maxExamples = 8);

// Runs core::collidePair for A and B on a CpuDevice, records its command stream and compares it
// on a fresh device that `makeCandidate` makes at the stream's size, over the pair's MOR. Pairs
// whose boxes do not overlap compare nothing. What the factory throws goes through.
// RECODE's command stream for the pair, drawn on `device` (the reference: a CpuDevice of the
// frame's size, left with the buffers the pair leaves), and the pair's MOR.
struct RecordedPair {
  raster::CommandStream stream;
  raster::PixelRect mor;
};
[[nodiscard]] RecordedPair recordPair(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                      const core::PairRequest& request,
                                      raster::DepthStencilDevice& device);

[[nodiscard]] ExactParityReport comparePairExactly(const core::TriangleMesh& a,
                                                   const core::TriangleMesh& b,
                                                   const core::PairRequest& request,
                                                   const core::DeviceFactory& makeCandidate);

// comparePairExactly on a backends::GlExactDevice of the platform, with its renderer. Throws
// std::runtime_error when the build has no exact GL device.
[[nodiscard]] ExactParityReport compareOnGlExact(
    const core::TriangleMesh& a, const core::TriangleMesh& b, const core::PairRequest& request,
    backends::GlPlatform platform = backends::GlPlatform::Auto);

// Which of the Vulkan devices compareOnVulkan draws on: the exact device with 64-bit shader
// arithmetic (`vulkan`), with 32-bit only (`vulkan-32`), or the compute device
// (`vulkan-compute`).
enum class VulkanOracleDevice { Native64, Emulated32, Compute };

// The same on that Vulkan device (the process's shared Vulkan context). Throws
// std::runtime_error when the build has no Vulkan device or no Vulkan driver is found.
[[nodiscard]] ExactParityReport compareOnVulkan(
    const core::TriangleMesh& a, const core::TriangleMesh& b, const core::PairRequest& request,
    VulkanOracleDevice device = VulkanOracleDevice::Native64);

// The exact GL device on `platform` as verify makes it, for what runs on many devices (a batch;
// the registry's factories take no platform): throws what compareOnGlExact throws when the
// device is missing.
[[nodiscard]] core::DeviceFactory glExactDeviceFactory(
    backends::GlPlatform platform = backends::GlPlatform::Auto);

}  // namespace recode::verify
