#pragma once
// Whether two pair results are the same answer: every field but the timing, compared exactly
// (doubles bit for bit, the case map and the contact points element by element). What a test of
// a new back end or of a batched path holds it to: an exact device must give collidePair's
// result on the CPU reference, field for field.

#include <optional>
#include <string>

#include "recode/pair/pair.hpp"

namespace recode::core {

// The first field in which `a` and `b` differ, named as in PairResult with the two values
// ("contact.maxDepth: 0.25 vs 0.5"), or nullopt when they are the same answer. PairTiming is
// not compared.
[[nodiscard]] std::optional<std::string> firstDifference(const PairResult& a, const PairResult& b);

}  // namespace recode::core
