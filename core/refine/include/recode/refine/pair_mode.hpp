#pragma once
// How a pair is decided (docs/algorithm.md, "Beyond the paper"): the paper's algorithm in the
// given frame (reference), refined on finer frames where a finer grid could change the answer
// (adaptive), or on blocks grown by one pixel and a few depth steps so that no contact is ever
// missed (conservative).

#include <optional>
#include <string_view>

namespace recode::core {

enum class PairMode { Reference, Adaptive, Conservative };

[[nodiscard]] std::string_view toString(PairMode mode);  // "reference", "adaptive", "conservative"
[[nodiscard]] std::optional<PairMode> parsePairMode(std::string_view name);  // nullopt if unknown

// The adaptive mode's answer: collide, apart, or apart at the refinement limit (a contact
// could not be ruled out above the bound).
enum class PairVerdict { Collide, Apart, ApartAtLimit };

[[nodiscard]] std::string_view toString(
    PairVerdict verdict);  // "collide", "apart", "apart_at_limit"

}  // namespace recode::core
