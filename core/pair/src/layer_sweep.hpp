#pragma once
// The layered pair's sweep at one pixel (docs/algorithm.md, "Closed meshes: the layered pair"),
// private to collideLayered and free of any device, so that it is tested on depths written by
// hand. Depths are the contract's 24-bit values: smaller is nearer.

#include <cstdint>
#include <span>
#include <vector>

#include "recode/pair/pair_cases.hpp"

namespace recode::core::detail {

using core::DepthInterval;  // pair_cases.hpp: [min, max]

// The depth intervals inside a closed mesh at a pixel, appended to `out` (which is cleared
// first): `entries` (its front-facing fragments' depths) and `exits` (its back-facing ones),
// as many of each, each sorted ascending. The i-th entry pairs with the i-th exit, each pair
// taken as [min, max] (rounding may put an entry a step beyond its exit where the surface is
// seen edge-on: that pair is counted in the return value), and pairs that overlap or touch
// are merged. Pairing the sorted lists is what a ray does in exact arithmetic, where entries
// and exits alternate along it; it needs no tie rule, since equal depths are interchangeable
// within either list. Returns the number of inverted pairs.
int insideIntervals(std::span<const std::uint32_t> entries, std::span<const std::uint32_t> exits,
                    std::vector<DepthInterval>& out);

// The intersection of two sorted, disjoint interval lists (insideIntervals' outputs), appended
// to `out` (cleared first): the depths inside both meshes at the pixel. An interval of one
// depth (min == max) is two meshes touching there.
void intersectIntervals(std::span<const DepthInterval> a, std::span<const DepthInterval> b,
                        std::vector<DepthInterval>& out);

// The summed length of the intervals, in depth steps.
[[nodiscard]] std::uint64_t totalLength(std::span<const DepthInterval> intervals);

// Whether every interval of `inner` lies within one interval of `outer` (both sorted and
// disjoint). True when `inner` is empty.
[[nodiscard]] bool liesWithin(std::span<const DepthInterval> inner,
                              std::span<const DepthInterval> outer);

}  // namespace recode::core::detail
