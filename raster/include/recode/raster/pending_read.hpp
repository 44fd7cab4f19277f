#pragma once
// A read-back whose values may arrive later: when the device has run the commands given before
// it (DepthStencilDevice::finish). A GPU device records a frame's pair tests and their
// read-backs into one submission and hands each read-back its values when the submission is
// done; a device that runs commands as they come (CpuDevice) hands them over at once.

#include <functional>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace recode::raster {

template <class T>
class PendingRead {
 public:
  // A read-back nobody has asked for: not ready, and never will be.
  PendingRead() = default;

  // A read-back with its values already known.
  [[nodiscard]] static PendingRead ready(std::vector<T> values) {
    PendingRead read = waiting();
    read.deliver(std::move(values));
    return read;
  }

  // A read-back the device will deliver to (it keeps a copy; the copies share the values).
  [[nodiscard]] static PendingRead waiting() {
    PendingRead read;
    read.state_ = std::make_shared<State>();
    return read;
  }

  // A read-back worked out from others: ready once `sourcesReady` says so, its values then
  // made by `make` (at the first take()). A device whose summaries are computed on the host
  // from its plain read-backs hands these out (DepthStencilDevice::summarizeLater).
  [[nodiscard]] static PendingRead derived(std::function<bool()> sourcesReady,
                                           std::function<std::vector<T>()> make) {
    PendingRead read = waiting();
    read.state_->sourcesReady = std::move(sourcesReady);
    read.state_->make = std::move(make);
    return read;
  }

  // Called by the device, once, when the values are known.
  void deliver(std::vector<T> values) {
    state_->values = std::move(values);
    state_->delivered = true;
  }

  [[nodiscard]] bool isReady() const {
    return state_ && (state_->delivered || (state_->make && state_->sourcesReady()));
  }

  // The values, moved out. Throws std::logic_error before the device has delivered them: the
  // caller forgot DepthStencilDevice::finish.
  [[nodiscard]] std::vector<T> take() {
    if (!isReady())
      throw std::logic_error("read-back taken before the device finished its commands");
    if (!state_->delivered) {
      state_->values = state_->make();
      state_->delivered = true;
      state_->make = nullptr;
      state_->sourcesReady = nullptr;
    }
    return std::move(state_->values);
  }

 private:
  struct State {
    bool delivered = false;
    std::vector<T> values;
    std::function<bool()> sourcesReady;  // with make: a derived read-back
    std::function<std::vector<T>()> make;
  };
  std::shared_ptr<State> state_;
};

}  // namespace recode::raster
