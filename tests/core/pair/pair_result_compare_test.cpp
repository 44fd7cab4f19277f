// firstDifference (pair_result_compare.hpp): the first field two pair results differ in, named
// with both values written so that any two different doubles read differently.

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>

#include "recode/pair/pair_result_compare.hpp"

using namespace recode;

TEST_CASE("a contact point that differs in its last bit is named, with 17 digits") {
  // Two results the same but for the first contact point's x, one unit in the last place apart:
  // 0.1 and the next double up read 0.10000000000000001 and 0.10000000000000002 at 17
  // significant digits (and both 0.1 at the stream's default 6).
  core::PairResult a;
  a.contact.points = {{0.1, 0.0, 0.0}, {1.0, 1.0, 1.0}};
  core::PairResult b = a;
  CHECK_FALSE(core::firstDifference(a, b).has_value());
  b.contact.points[0].x() = std::nextafter(0.1, 1.0);
  CHECK(core::firstDifference(a, b).value_or("") ==
        "contact.points[0]: (0.10000000000000001, 0, 0) vs (0.10000000000000002, 0, 0)");
}
