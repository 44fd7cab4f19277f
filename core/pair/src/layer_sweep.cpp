#include "layer_sweep.hpp"

#include <algorithm>
#include <cstddef>

#include "recode/raster/invariants.hpp"

namespace recode::core::detail {

int insideIntervals(std::span<const std::uint32_t> entries, std::span<const std::uint32_t> exits,
                    std::vector<DepthInterval>& out) {
  RECODE_INVARIANT(entries.size() == exits.size(), "a closed mesh has an exit for every entry");
  out.clear();
  int inverted = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::uint32_t e = entries[i], x = exits[i];
    inverted += e > x ? 1 : 0;
    // Both lists are sorted, so the pairs' lower ends (and upper ends) are too: a pair can only
    // meet the one before it.
    const DepthInterval pair{std::min(e, x), std::max(e, x)};
    if (!out.empty() && pair.min <= out.back().max)
      out.back().max = std::max(out.back().max, pair.max);
    else
      out.push_back(pair);
  }
  return inverted;
}

void intersectIntervals(std::span<const DepthInterval> a, std::span<const DepthInterval> b,
                        std::vector<DepthInterval>& out) {
  out.clear();
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const std::uint32_t lo = std::max(a[i].min, b[j].min);
    const std::uint32_t hi = std::min(a[i].max, b[j].max);
    if (lo <= hi)
      out.push_back({lo, hi});
    // The interval that ends first can meet nothing further in the other list.
    if (a[i].max < b[j].max)
      ++i;
    else
      ++j;
  }
}

std::uint64_t totalLength(std::span<const DepthInterval> intervals) {
  std::uint64_t sum = 0;
  for (const DepthInterval& d : intervals)
    sum += d.max - d.min;
  return sum;
}

bool liesWithin(std::span<const DepthInterval> inner, std::span<const DepthInterval> outer) {
  std::size_t j = 0;
  for (const DepthInterval& d : inner) {
    while (j < outer.size() && outer[j].max < d.min)
      ++j;
    if (j == outer.size() || outer[j].min > d.min || outer[j].max < d.max)
      return false;
  }
  return true;
}

}  // namespace recode::core::detail
