// newTriangleSourceKey (triangle_source.hpp): a key no other call in the process returns, never
// 0 (0 is contentKey's "no key", which a device never records or replays under).

#include <catch2/catch.hpp>

#include <cstdint>
#include <set>

#include "recode/raster/triangle_source.hpp"

namespace {

// The process's first two keys: taken while static objects are made, before any test runs (no
// other static object of this program makes a key), so that whatever order the tests run in,
// the keys at the very start of the counter are checked.
const std::uint64_t kFirstKeys[2] = {recode::raster::newTriangleSourceKey(),
                                     recode::raster::newTriangleSourceKey()};

}  // namespace

TEST_CASE("triangle source keys are never 0 and never repeat, from the process's first on",
          "[raster][source-key]") {
  std::set<std::uint64_t> seen{kFirstKeys[0], kFirstKeys[1]};
  CHECK(kFirstKeys[0] != 0);
  CHECK(kFirstKeys[1] != 0);
  CHECK(seen.size() == 2);
  for (int k = 0; k < 100; ++k) {
    const std::uint64_t key = recode::raster::newTriangleSourceKey();
    CHECK(key != 0);
    CHECK(seen.insert(key).second);
  }
}
