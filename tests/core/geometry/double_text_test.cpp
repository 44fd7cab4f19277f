// The mesh readers read coordinates with recode::io::readDoubleText and messages print them
// with shortestText; where the standard library has no floating-point from_chars / to_chars
// (the WebAssembly build) the portable versions serve. They must give the same answers: here
// they are compared with the standard library's on random and chosen doubles and texts.
#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "recode/io/double_text.hpp"

namespace {

using recode::io::detail::readDoubleTextPortable;
using recode::io::detail::shortestTextPortable;

std::string standardText(double v) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

std::vector<double> chosenDoubles() {
  const double inf = std::numeric_limits<double>::infinity();
  return {0.0,
          -0.0,
          1.0,
          -2.0,
          0.1,
          1e-300,
          1e300,
          123456789.0,
          1e15,
          1e16,
          1e17,
          1e21,
          1e22,
          1e23,
          1e-5,
          1e-4,
          0.001,
          1234.5,
          5e-324,
          2.2250738585072014e-308,
          1.7976931348623157e308,
          inf,
          -inf,
          100.0,
          1000000.0,
          0.3,
          2.0 / 3,
          -1.0 / 3,
          4.35,
          9007199254740993.0,
          123e-20,
          1.5e-7};
}

}  // namespace

TEST_CASE("shortestTextPortable gives std::to_chars's text", "[double_text]") {
  std::vector<double> values = chosenDoubles();
  std::mt19937_64 random(20261127);
  for (int i = 0; i < 200000; ++i) {
    std::uint64_t bits = random();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isnan(v))
      values.push_back(v);
    values.push_back(
        std::ldexp(static_cast<double>(random() % 100000), -static_cast<int>(random() % 40)));
    values.push_back(static_cast<double>(random() % 1000000) / 1000.0);
  }
  std::size_t differ = 0;
  std::string first;
  for (double v : values) {
    if (shortestTextPortable(v) != standardText(v)) {
      if (differ++ == 0)
        first = standardText(v) + " printed as " + shortestTextPortable(v);
    }
  }
  INFO(values.size() << " doubles, first difference: " << first);
  CHECK(differ == 0);
  CHECK(shortestTextPortable(std::nan("")) == "nan");
  CHECK(shortestTextPortable(-std::nan("")) == "-nan");
}

TEST_CASE("readDoubleTextPortable reads as std::from_chars does", "[double_text]") {
  std::vector<std::string> texts = {"0",
                                    "-0",
                                    "1",
                                    "-2.5",
                                    "0.1",
                                    "1e-300",
                                    "1e400",
                                    "-1e400",
                                    "1e-400",
                                    "4.9e-324",
                                    ".5",
                                    "5.",
                                    "1e",
                                    "1e+",
                                    "1e+5x",
                                    "inf",
                                    "-INF",
                                    "infinity",
                                    "nan",
                                    "NaN(123)",
                                    "+1",
                                    " 1",
                                    "0x10",
                                    "-",
                                    "",
                                    ".",
                                    "e5",
                                    "12abc",
                                    "1.2.3",
                                    "00012.5000",
                                    "2.2250738585072011e-308",
                                    "9007199254740993",
                                    "1.00000000000000011102230246251565404236316680908203125"};
  std::mt19937_64 random(7);
  for (int i = 0; i < 100000; ++i) {
    std::uint64_t bits = random();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", static_cast<int>(random() % 20) + 1, v);
    texts.emplace_back(buffer);
  }
  std::size_t differ = 0;
  std::string first;
  for (const std::string& t : texts) {
    double expected = 0.0;
    const auto e = std::from_chars(t.data(), t.data() + t.size(), expected);
    const auto got = readDoubleTextPortable(t.data(), t.data() + t.size());
    const bool same =
        e.ptr == got.end && e.ec == got.error &&
        (e.ec != std::errc{} ||
         (std::isnan(expected) ? std::isnan(got.value)
                               : std::memcmp(&expected, &got.value, sizeof expected) == 0));
    if (!same && differ++ == 0)
      first = "'" + t + "'";
  }
  INFO(texts.size() << " texts, first difference: " << first);
  CHECK(differ == 0);
}
