#pragma once
// A compute shader run once over a buffer of records on the logical device of the Vulkan devices
// with 32-bit shader arithmetic (lavapipe here): for testing shader functions on their own, with
// the device's own context, so that what runs is what the device's shaders may use.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace recode::testing {

class ComputeHarness {
 public:
  // The SPIR-V of a compute shader with a readonly storage buffer at binding 0, a storage buffer
  // at binding 1 and a push-constant block of `pushBytes`, local size 64 in x.
  ComputeHarness(std::span<const std::uint32_t> spirv, std::uint32_t pushBytes);
  ~ComputeHarness();
  ComputeHarness(const ComputeHarness&) = delete;
  ComputeHarness& operator=(const ComputeHarness&) = delete;

  // Runs `count` invocations (rounded up to whole groups of 64) on `input`, with the push
  // constants `push`, and returns the first `outputBytes` of binding 1.
  [[nodiscard]] std::vector<std::uint8_t> run(std::span<const std::uint8_t> input,
                                              std::size_t outputBytes, std::uint32_t count,
                                              std::span<const std::uint8_t> push);

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace recode::testing
