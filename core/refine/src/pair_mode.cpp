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

std::optional<PairMode> parsePairMode(std::string_view name) {
  for (const PairMode mode :
       {PairMode::Reference, PairMode::Adaptive, PairMode::Conservative, PairMode::SkipApart})
    if (name == toString(mode))
      return mode;
  return std::nullopt;
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
