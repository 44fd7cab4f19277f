#include "recode/verify/exact_parity.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "recode/raster/cpu_device.hpp"
#ifdef RECODE_HAVE_GL_EXACT
#include "recode/backends/gl_exact_device.hpp"
#endif
#ifdef RECODE_HAVE_VULKAN
#include "recode/backends/vulkan_compute_device.hpp"
#include "recode/backends/vulkan_device.hpp"
#endif

namespace recode::verify {

namespace {

void requireStreamSize(const raster::DepthStencilDevice& device,
                       const raster::CommandStream& stream, const char* which) {
  if (device.width() != stream.width || device.height() != stream.height) {
    throw std::invalid_argument(std::string("exact parity: the ") + which + " device is " +
                                std::to_string(device.width()) + "x" +
                                std::to_string(device.height()) + " but the stream is " +
                                std::to_string(stream.width) + "x" + std::to_string(stream.height));
  }
}

void compareRegion(const raster::DepthStencilDevice& reference,
                   const raster::DepthStencilDevice& candidate, const raster::PixelRect& region,
                   int command, int maxExamples, ExactParityReport& report) {
  const auto refDepth = reference.readDepth(region);
  const auto refStencil = reference.readStencil(region);
  const auto gotDepth = candidate.readDepth(region);
  const auto gotStencil = candidate.readStencil(region);
  ++report.comparisons;
  for (std::size_t i = 0; i < refDepth.size(); ++i) {
    ++report.counts.pixels;
    if (refDepth[i] == gotDepth[i] && refStencil[i] == gotStencil[i]) {
      ++report.counts.identical;
      continue;
    }
    ++report.counts.different;
    if (static_cast<int>(report.examples.size()) < maxExamples) {
      const int w = region.width();
      report.examples.push_back({command, region.x0 + static_cast<int>(i) % w,
                                 region.y0 + static_cast<int>(i) / w, refStencil[i], gotStencil[i],
                                 refDepth[i], gotDepth[i]});
    }
  }
}

}  // namespace

RecordedPair recordPair(const core::TriangleMesh& a, const core::TriangleMesh& b,
                        const core::PairRequest& request, raster::DepthStencilDevice& device) {
  raster::RecordingDevice recorder(device);
  const core::PairResult result = core::collidePair(recorder, a, b, request);
  return {recorder.stream(), result.mor};
}

ExactParityReport compareStreamExactly(const raster::CommandStream& stream,
                                       raster::DepthStencilDevice& reference,
                                       raster::DepthStencilDevice& candidate,
                                       std::optional<raster::PixelRect> region, int maxExamples) {
  requireStreamSize(reference, stream, "reference");
  requireStreamSize(candidate, stream, "candidate");
  const raster::PixelRect frame{0, 0, stream.width, stream.height};
  const raster::PixelRect compared = region ? region->intersect(frame) : frame;
  ExactParityReport report;
  if (compared.empty())
    return report;
  compareRegion(reference, candidate, compared, -1, maxExamples, report);
  for (std::size_t k = 0; k < stream.commands.size(); ++k) {
    const std::vector<raster::Command> one{stream.commands[k]};
    raster::replay(one, reference);
    raster::replay(one, candidate);
    if (raster::changesBuffers(one.front()))
      compareRegion(reference, candidate, compared, static_cast<int>(k), maxExamples, report);
  }
  return report;
}

ExactParityReport comparePairExactly(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                     const core::PairRequest& request,
                                     const core::DeviceFactory& makeCandidate) {
  raster::CpuDevice cpu(request.frame.width, request.frame.height);
  const RecordedPair pair = recordPair(a, b, request, cpu);
  if (pair.mor.empty())
    return {};
  const raster::CommandStream& stream = pair.stream;
  raster::CpuDevice reference(stream.width, stream.height);
  const std::unique_ptr<raster::DepthStencilDevice> candidate =
      makeCandidate(stream.width, stream.height);
  return compareStreamExactly(stream, reference, *candidate, pair.mor);
}

namespace {

// comparePairExactly on a Device(width, height, extra...) that names its renderer, which the
// report keeps.
template <class Device, class... Extra>
ExactParityReport compareOnDeviceWithRenderer(const core::TriangleMesh& a,
                                              const core::TriangleMesh& b,
                                              const core::PairRequest& request, Extra... extra) {
  std::string renderer;
  ExactParityReport report = comparePairExactly(a, b, request, [&](int width, int height) {
    auto device = std::make_unique<Device>(width, height, extra...);
    renderer = device->renderer();
    return device;
  });
  report.renderer = renderer;
  return report;
}

}  // namespace

#ifndef RECODE_HAVE_GL_EXACT
ExactParityReport compareOnGlExact(const core::TriangleMesh&, const core::TriangleMesh&,
                                   const core::PairRequest&, backends::GlPlatform) {
  throw std::runtime_error(
      "this build has no exact GL device (Debian: apt-get install "
      "libosmesa6-dev or libegl-dev, then reconfigure)");
}

core::DeviceFactory glExactDeviceFactory(backends::GlPlatform) {
  return [](int, int) -> std::unique_ptr<raster::DepthStencilDevice> {
    throw std::runtime_error(
        "this build has no exact GL device (Debian: apt-get install "
        "libosmesa6-dev or libegl-dev, then reconfigure)");
  };
}
#else
ExactParityReport compareOnGlExact(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                   const core::PairRequest& request,
                                   backends::GlPlatform platform) {
  return compareOnDeviceWithRenderer<backends::GlExactDevice>(a, b, request, platform);
}

core::DeviceFactory glExactDeviceFactory(backends::GlPlatform platform) {
  return [platform](int width, int height) -> std::unique_ptr<raster::DepthStencilDevice> {
    return std::make_unique<backends::GlExactDevice>(width, height, platform);
  };
}
#endif

#ifndef RECODE_HAVE_VULKAN
ExactParityReport compareOnVulkan(const core::TriangleMesh&, const core::TriangleMesh&,
                                  const core::PairRequest&, VulkanOracleDevice) {
  throw std::runtime_error(
      "this build has no Vulkan device (Debian: apt-get install libvulkan-dev glslang-tools "
      "mesa-vulkan-drivers, then reconfigure)");
}
#else
ExactParityReport compareOnVulkan(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                  const core::PairRequest& request, VulkanOracleDevice device) {
  switch (device) {
    case VulkanOracleDevice::Emulated32:
      return compareOnDeviceWithRenderer<backends::VulkanDevice>(
          a, b, request, backends::ShaderArithmetic::Emulated32);
    case VulkanOracleDevice::Compute:
      return compareOnDeviceWithRenderer<backends::VulkanComputeDevice>(a, b, request);
    default:
      return compareOnDeviceWithRenderer<backends::VulkanDevice>(
          a, b, request, backends::ShaderArithmetic::Native64);
  }
}
#endif

}  // namespace recode::verify
