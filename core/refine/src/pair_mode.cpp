#include "recode/refine/pair_mode.hpp"

namespace recode::core {

std::string_view toString(PairMode mode) {
  switch (mode) {
    case PairMode::Reference:
      return "reference";
    case PairMode::Adaptive:
      return "adaptive";
    case PairMode::Conservative:
      return "conservative";
    case PairMode::SkipApart:
      return "skip-apart";
  }
  return "?";
}

namespace {

constexpr PairMode kPairModes[] = {PairMode::Reference, PairMode::Adaptive, PairMode::Conservative,
                                   PairMode::SkipApart};

}  // namespace

std::optional<PairMode> parsePairMode(std::string_view name) {
  for (const PairMode mode : kPairModes)
    if (name == toString(mode))
      return mode;
  return std::nullopt;
}

std::vector<std::string> pairModeNames() {
  std::vector<std::string> names;
  for (const PairMode mode : kPairModes)
    names.emplace_back(toString(mode));
  return names;
}

std::string_view toString(PairVerdict verdict) {
  switch (verdict) {
    case PairVerdict::Collide:
      return "collide";
    case PairVerdict::Apart:
      return "apart";
    case PairVerdict::ApartAtLimit:
      return "apart_at_limit";
  }
  return "?";
}

}  // namespace recode::core
