#pragma once
// A device that hands every command to another device: the base of a device that adds to one
// (counts draws, records commands, alters them on purpose in a test) without writing the whole
// interface again. Only drawMesh is not forwarded: it keeps the seam's default, so the inner
// device sees every block drawn whole through drawTriangles, as a GPU back end draws it, and an
// override of drawTriangles sees every draw.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "recode/raster/device.hpp"

namespace recode::raster {

class ForwardingDevice : public DepthStencilDevice {
 public:
  // Forwards to `inner`, which must outlive this device.
  explicit ForwardingDevice(DepthStencilDevice& inner) : inner_(&inner) {}
  // Forwards to `inner`, which this device owns. Throws std::invalid_argument for none.
  explicit ForwardingDevice(std::unique_ptr<DepthStencilDevice> inner);

  [[nodiscard]] int width() const override { return inner_->width(); }
  [[nodiscard]] int height() const override { return inner_->height(); }
  void setScissor(const PixelRect& rect) override { inner_->setScissor(rect); }
  void clearDepth(double depth) override { inner_->clearDepth(depth); }
  void clearStencil(std::uint8_t value) override { inner_->clearStencil(value); }
  void setDepthFunc(CompareFunc func) override { inner_->setDepthFunc(func); }
  void setDepthWriteMask(bool write) override { inner_->setDepthWriteMask(write); }
  void setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) override {
    inner_->setStencilFunc(func, ref, valueMask);
  }
  void setStencilOps(Face face, const StencilOps& ops) override {
    inner_->setStencilOps(face, ops);
  }
  void setStencilWriteMask(std::uint8_t mask) override { inner_->setStencilWriteMask(mask); }
  void setCullMode(CullMode mode) override { inner_->setCullMode(mode); }
  void drawTriangles(std::span<const WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override {
    inner_->drawTriangles(vertices, indices);
  }
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const PixelRect& rect) const override {
    return inner_->readStencil(rect);
  }
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const PixelRect& rect) const override {
    return inner_->readDepth(rect);
  }

  [[nodiscard]] PendingRead<std::uint8_t> readStencilLater(const PixelRect& rect) override {
    return inner_->readStencilLater(rect);
  }
  [[nodiscard]] PendingRead<std::uint32_t> readDepthLater(const PixelRect& rect) override {
    return inner_->readDepthLater(rect);
  }
  [[nodiscard]] std::shared_ptr<const KeptDepth> keepDepthLater(const PixelRect& rect) override {
    return inner_->keepDepthLater(rect);
  }
  [[nodiscard]] PendingRead<PixelSummary> summarizeLater(const PixelRect& rect,
                                                         const StencilClasses& classes,
                                                         const KeptDepth* nearEnd) override {
    return inner_->summarizeLater(rect, classes, nearEnd);
  }
  void finish() override { inner_->finish(); }
  [[nodiscard]] bool defers() const override { return inner_->defers(); }
  [[nodiscard]] TransferCounters transfers() const override { return inner_->transfers(); }

  [[nodiscard]] DepthStencilDevice& inner() { return *inner_; }
  [[nodiscard]] const DepthStencilDevice& inner() const { return *inner_; }

 private:
  std::unique_ptr<DepthStencilDevice> owned_;
  DepthStencilDevice* inner_;
};

}  // namespace recode::raster
