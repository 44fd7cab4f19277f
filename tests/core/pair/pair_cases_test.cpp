// The case table itself (docs/algorithm.md section 1) and its stencil encoding, no device.

#include <catch2/catch.hpp>
#include <optional>

#include "recode/pair/pair_cases.hpp"

using recode::core::caseFromIntervals;
using recode::core::caseFromStencil;
using recode::core::DepthInterval;

namespace {

// The rows of the table exactly as written in docs/algorithm.md, one predicate each.
bool row(int c, long amin, long amax, long bmin, long bmax) {
  switch (c) {
    case 2:
      return amax < bmin;
    case 3:
      return amin <= bmin && bmin <= amax && amax < bmax;
    case 4:
      return bmin < amin && amax < bmax;
    case 5:
      return amin <= bmin && bmax <= amax;
    case 6:
      return bmin < amin && amin <= bmax && bmax <= amax;
    case 7:
      return bmax < amin;
    default:
      return false;
  }
}

}  // namespace

TEST_CASE("the table's rows 2-7 partition every pair of closed intervals") {
  int checked = 0;
  for (long amin = 0; amin < 6; ++amin)
    for (long amax = amin; amax < 6; ++amax)
      for (long bmin = 0; bmin < 6; ++bmin)
        for (long bmax = bmin; bmax < 6; ++bmax) {
          int matches = 0, matched = -1;
          for (int c = 2; c <= 7; ++c)
            if (row(c, amin, amax, bmin, bmax)) {
              ++matches;
              matched = c;
            }
          INFO("A [" << amin << ", " << amax << "] B [" << bmin << ", " << bmax << "]");
          REQUIRE(matches == 1);
          const auto a =
              DepthInterval{static_cast<std::uint32_t>(amin), static_cast<std::uint32_t>(amax)};
          const auto b =
              DepthInterval{static_cast<std::uint32_t>(bmin), static_cast<std::uint32_t>(bmax)};
          CHECK(caseFromIntervals(a, b) == matched);
          // Interference is exactly "the closed intervals share a value".
          CHECK(recode::core::isInterfering(matched) == (amin <= bmax && bmin <= amax));
          ++checked;
        }
  CHECK(checked == 441);
}

TEST_CASE("coverage cases and swapped interval ends") {
  CHECK(caseFromIntervals(std::nullopt, std::nullopt) == 0);
  CHECK(caseFromIntervals(DepthInterval{3, 5}, std::nullopt) == 1);
  CHECK(caseFromIntervals(std::nullopt, DepthInterval{3, 5}) == 8);
  // An interval given max-first is read with its ends swapped.
  CHECK(caseFromIntervals(DepthInterval{5, 3}, DepthInterval{4, 9}) == 3);
  CHECK(caseFromIntervals(DepthInterval{3, 5}, DepthInterval{9, 4}) == 3);
}

TEST_CASE("stencil decoding: count bits and the two Amin bits") {
  // Count 0 (A absent): B's coverage shows in bits 2 and 3.
  CHECK(caseFromStencil(0x00) == 0);
  CHECK(caseFromStencil(0x0C) == 8);
  // Count 1: no face of B at or before Amax.
  CHECK(caseFromStencil(0x01) == 1);
  CHECK(caseFromStencil(0x0D) == 2);
  // Count 2: B's near end within A's reach; both faces at or behind Amin -> 3, else 4.
  CHECK(caseFromStencil(0x0E) == 3);
  CHECK(caseFromStencil(0x0A) == 4);
  CHECK(caseFromStencil(0x06) == 4);
  // Count 3: both faces at or before Amax; how many at or behind Amin separates 5, 6, 7.
  CHECK(caseFromStencil(0x0F) == 5);
  CHECK(caseFromStencil(0x0B) == 6);
  CHECK(caseFromStencil(0x07) == 6);
  CHECK(caseFromStencil(0x03) == 7);
  // Bits above the encoding are ignored.
  CHECK(caseFromStencil(0xF3) == 7);
}

TEST_CASE("case names: the nine cases by number and any other number invalid") {
  // The names in the table's order, rows 0..8 (the case numbers classify gives).
  const char* const names[] = {"neither block",
                               "A only",
                               "B behind A",
                               "B enters A from behind",
                               "B spans A",
                               "A spans B",
                               "B enters A from the front",
                               "B in front of A",
                               "B only"};
  for (int c = 0; c < recode::core::kCaseCount; ++c) {
    CAPTURE(c);
    CHECK(recode::core::caseName(c) == names[c]);
  }
  // One past the last case and one before the first are no case.
  CHECK(recode::core::caseName(recode::core::kCaseCount) == "invalid case");
  CHECK(recode::core::caseName(-1) == "invalid case");
}
