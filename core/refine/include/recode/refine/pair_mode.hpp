#pragma once
// How a pair is decided (docs/algorithm.md, "Beyond the paper"): the paper's algorithm in the
// given frame (reference), refined on finer frames where a finer grid could change the answer
// (adaptive), or on blocks grown by one pixel and a few depth steps so that no contact is ever
// missed (conservative); or the reference with pairs proven apart left undrawn (skip-apart).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace recode::core {

// SkipApart: the reference, except that a pair provenApart (proven_apart.hpp) in its frame is
// not drawn; verdicts and contact regions are the reference's, what is drawn and read is less.
enum class PairMode { Reference, Adaptive, Conservative, SkipApart };

[[nodiscard]] std::string_view toString(
    PairMode mode);  // "reference", "adaptive", "conservative", "skip-apart"
[[nodiscard]] std::optional<PairMode> parsePairMode(std::string_view name);  // nullopt if unknown
// Every mode's name, in the enum's order: the choices a command line or binding offers.
[[nodiscard]] std::vector<std::string> pairModeNames();

// The adaptive mode's answer: collide, apart, or apart at the refinement limit (a contact
// could not be ruled out above the bound).
enum class PairVerdict { Collide, Apart, ApartAtLimit };

[[nodiscard]] std::string_view toString(
    PairVerdict verdict);  // "collide", "apart", "apart_at_limit"

}  // namespace recode::core
