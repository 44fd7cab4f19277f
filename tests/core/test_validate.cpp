#include <catch2/catch.hpp>
TEST_CASE("placeholder validate") {
  CHECK(1 + 1 == 2);
}
