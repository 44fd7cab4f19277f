// DepthStencilDevice's summaries from its plain read-backs, for devices that reduce nothing
// themselves.
#include "recode/raster/device.hpp"

#include <stdexcept>
#include <utility>

namespace recode::raster {

namespace {

// The depth kept as a read-back of its values.
class HostKeptDepth final : public KeptDepth {
 public:
  HostKeptDepth(const DepthStencilDevice& keeper, const PixelRect& over,
                PendingRead<std::uint32_t> kept)
      : KeptDepth(&keeper, over), values(std::move(kept)) {}
  PendingRead<std::uint32_t> values;
};

}  // namespace

void KeptDepth::requireKeptBy(const void* keeper, const PixelRect& rect) const {
  if (keeper != keeper_ || rect != rect_)
    throw std::invalid_argument(
        "summarizeLater: the near end was not kept by this device over this rectangle");
}

std::shared_ptr<const KeptDepth> DepthStencilDevice::keepDepthLater(const PixelRect& rect) {
  const PixelRect r = rect.intersect({0, 0, width(), height()});
  return std::make_shared<HostKeptDepth>(*this, r, readDepthLater(r));
}

PendingRead<PixelSummary> DepthStencilDevice::summarizeLater(const PixelRect& rect,
                                                             const StencilClasses& classes,
                                                             const KeptDepth* nearEnd) {
  const PixelRect r = rect.intersect({0, 0, width(), height()});
  const auto* kept = dynamic_cast<const HostKeptDepth*>(nearEnd);
  if (nearEnd != nullptr) {
    nearEnd->requireKeptBy(this, r);
    if (kept == nullptr)  // kept by this device in memory of its own, not read back
      throw std::logic_error(
          "summarizeLater: a depth the device kept itself reached the read-back summary");
  }
  PendingRead<std::uint8_t> stencil = readStencilLater(r);
  PendingRead<std::uint32_t> nearDepth = kept ? kept->values : PendingRead<std::uint32_t>();
  PendingRead<std::uint32_t> farDepth = kept ? readDepthLater(r) : PendingRead<std::uint32_t>();
  const bool withDepth = kept != nullptr;
  return PendingRead<PixelSummary>::derived(
      [=] {
        return stencil.isReady() && (!withDepth || (nearDepth.isReady() && farDepth.isReady()));
      },
      [=]() mutable {
        const std::vector<std::uint8_t> s = stencil.take();
        std::vector<std::uint32_t> n, f;
        if (withDepth) {
          n = nearDepth.take();
          f = farDepth.take();
        }
        return std::vector<PixelSummary>{summarizePixels(r, s, n, f, classes)};
      });
}

}  // namespace recode::raster
