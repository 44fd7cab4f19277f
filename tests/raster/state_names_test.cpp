// The GL names of the state enumerations (state.hpp), as command files spell them: each value's
// name and back, and no value for a name that is not one of them, the empty name included.

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "recode/raster/state.hpp"

using namespace recode::raster;

TEST_CASE("state names go to their values and back, and nothing else is a name", "[state][names]") {
  const char* compare[] = {"NEVER",   "LESS",     "EQUAL",  "LEQUAL",
                           "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS"};
  for (int k = 0; k < 8; ++k) {
    const auto f = static_cast<CompareFunc>(k);
    CHECK(toString(f) == compare[k]);
    CHECK(parseCompareFunc(compare[k]) == f);
  }
  const char* ops[] = {"KEEP",      "ZERO", "REPLACE",   "INCR",
                       "INCR_WRAP", "DECR", "DECR_WRAP", "INVERT"};
  for (int k = 0; k < 8; ++k) {
    const auto op = static_cast<StencilOp>(k);
    CHECK(toString(op) == ops[k]);
    CHECK(parseStencilOp(ops[k]) == op);
  }
  const char* faces[] = {"front", "back", "both"};
  const char* culls[] = {"none", "front", "back"};
  for (int k = 0; k < 3; ++k) {
    CHECK(toString(static_cast<Face>(k)) == faces[k]);
    CHECK(parseFace(faces[k]) == static_cast<Face>(k));
    CHECK(toString(static_cast<CullMode>(k)) == culls[k]);
    CHECK(parseCullMode(culls[k]) == static_cast<CullMode>(k));
  }
  // Exactly 8, 8, 3 and 3 names: no further value has one, and the empty string is no name.
  for (const std::string bad : {"", "less", "BOTH", "NONE "}) {
    INFO("'" << bad << "'");
    CHECK_FALSE(parseCompareFunc(bad));
    CHECK_FALSE(parseStencilOp(bad));
    CHECK_FALSE(parseFace(bad));
    CHECK_FALSE(parseCullMode(bad));
  }
  CHECK_THROWS_AS(toString(static_cast<CompareFunc>(8)), std::out_of_range);
  CHECK_THROWS_AS(toString(static_cast<StencilOp>(8)), std::out_of_range);
  CHECK_THROWS_AS(toString(static_cast<Face>(3)), std::out_of_range);
  CHECK_THROWS_AS(toString(static_cast<CullMode>(3)), std::out_of_range);
}
