// LibstdcxxHashOrder keeps the order libstdc++'s std::unordered_map lists its keys in; the
// convex hull's faces and clipped blocks' caps start their loops at its first key. Here it is
// compared with libstdc++'s own map (in a build with libstdc++) over random insertions and
// erasures, small maps and large, keys that share buckets and keys that do not.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include "recode/geometry/hash_order.hpp"

using recode::core::LibstdcxxHashOrder;

TEST_CASE("LibstdcxxHashOrder's first key is libstdc++'s begin()", "[hash_order]") {
#if !defined(__GLIBCXX__)
  WARN("not built with libstdc++: nothing to compare with");
#else
  std::mt19937 random(20261127);
  long long checks = 0, differ = 0;
  std::string first;
  for (int trial = 0; trial < 3000; ++trial) {
    // Key ranges from crowded (many keys per bucket) to sparse, sizes across several rehashes.
    const auto range = static_cast<std::uint32_t>(1u + random() % (trial % 3 == 0 ? 40u : 100000u));
    const int inserts = 1 + static_cast<int>(random() % (trial % 10 == 0 ? 700u : 40u));
    std::unordered_map<std::uint32_t, int> map;
    LibstdcxxHashOrder order;
    std::vector<std::uint32_t> present;
    for (int i = 0; i < inserts; ++i) {
      const std::uint32_t key = static_cast<std::uint32_t>(random() % range);
      if (map.emplace(key, i).second) {
        order.insert(key);
        present.push_back(key);
      }
      // Now and then an erasure, as a cap's loop walk does.
      if (!present.empty() && random() % 4 == 0) {
        const std::size_t at = random() % present.size();
        map.erase(present[at]);
        order.erase(present[at]);
        present.erase(present.begin() + static_cast<std::ptrdiff_t>(at));
      }
      CHECK(order.empty() == map.empty());
      if (map.empty())
        continue;
      ++checks;
      if (order.first() != map.begin()->first && differ++ == 0)
        first = "trial " + std::to_string(trial) + " after " + std::to_string(i + 1) + " steps";
    }
  }
  INFO(checks << " maps compared; first difference: " << first);
  CHECK(checks > 100000);
  CHECK(differ == 0);
#endif
}

TEST_CASE("LibstdcxxHashOrder refuses what a map cannot do", "[hash_order]") {
  LibstdcxxHashOrder order;
  CHECK_THROWS_AS((void)order.first(), std::logic_error);
  order.insert(7);
  CHECK_THROWS_AS(order.erase(8), std::logic_error);
  order.erase(7);
  CHECK(order.empty());
}
