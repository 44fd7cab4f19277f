#pragma once
// The depth read-back of every exact GPU device: the attachment holds the contract's 24-bit q as
// the float q 2^-24 (exact, and ordered as q is), so a read-back of 32-bit floats is turned back
// into q here, and anything else is reported rather than rounded.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace recode::backends {

// The q of each tightly packed 32-bit float of `bytes`. Throws std::runtime_error naming
// `device` ("Vulkan device: the depth buffer holds ..., not a multiple of 2^-24 below 1") for a
// value that is not some q 2^-24 with 0 <= q < 2^24: the driver converted depth on the way.
[[nodiscard]] std::vector<std::uint32_t> depthFromStoredFloats(std::span<const std::uint8_t> bytes,
                                                               std::string_view device);

}  // namespace recode::backends
