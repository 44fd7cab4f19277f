// The vulkan-32 device's promise to GPUs without 64-bit arithmetic, checked on its embedded
// SPIR-V: no module it runs declares the Float64 or the Int64 capability, so a driver without
// shaderFloat64 and shaderInt64 accepts it. The 64-bit device's modules are scanned too, to
// show that the scan finds those capabilities where they are.

#include <catch2/catch.hpp>

#include <cstdint>
#include <set>
#include <span>

#include "vulkan_spirv.hpp"

namespace {
using std::uint32_t;  // glslangValidator --vn writes `const uint32_t k_<name>[] = {...};`
#include "contract32_ops.comp.h"
}  // namespace

using recode::backends::ShaderArithmetic;
using recode::backends::detail::spirvModules;

namespace {

constexpr std::uint32_t kMagic = 0x07230203;
constexpr std::uint32_t kOpCapability = 17;
constexpr std::uint32_t kFloat64 = 10;
constexpr std::uint32_t kInt64 = 11;

// Every capability a module declares: its instructions follow the 5-word header, each word
// count in the high half of its first word and opcode in the low half.
std::set<std::uint32_t> capabilities(std::span<const std::uint32_t> words) {
  REQUIRE(words.size() > 5);
  REQUIRE(words[0] == kMagic);
  std::set<std::uint32_t> found;
  std::size_t i = 5;
  while (i < words.size()) {
    const std::uint32_t count = words[i] >> 16;
    const std::uint32_t opcode = words[i] & 0xFFFFu;
    REQUIRE(count >= 1);
    REQUIRE(i + count <= words.size());
    if (opcode == kOpCapability)
      found.insert(words[i + 1]);
    i += count;
  }
  return found;
}

bool declares64Bit(std::span<const std::uint32_t> words) {
  const std::set<std::uint32_t> c = capabilities(words);
  return c.count(kFloat64) != 0 || c.count(kInt64) != 0;
}

}  // namespace

TEST_CASE("the vulkan-32 device's SPIR-V declares neither Float64 nor Int64", "[vulkan-32]") {
  const auto m = spirvModules(ShaderArithmetic::Emulated32);
  CHECK_FALSE(declares64Bit(m.exactVertex));
  CHECK_FALSE(declares64Bit(m.exactFragment));
  CHECK_FALSE(declares64Bit(m.clearVertex));
  CHECK_FALSE(declares64Bit(m.clearFragment));
  // The arithmetic test's shader runs the same library.
  CHECK_FALSE(declares64Bit(k_contract32_ops_comp));
}

TEST_CASE("the capability scan finds Float64 and Int64 in the 64-bit device's SPIR-V",
          "[vulkan-32]") {
  const auto m = spirvModules(ShaderArithmetic::Native64);
  const std::set<std::uint32_t> fragment = capabilities(m.exactFragment);
  CHECK(fragment.count(kFloat64) == 1);
  CHECK(fragment.count(kInt64) == 1);
  CHECK(declares64Bit(m.exactVertex));
  CHECK(declares64Bit(m.exactFragment));
  CHECK_FALSE(declares64Bit(m.clearFragment));
}
