#include "recode/io/double_text.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace recode::io {

// libc++ of emscripten 3.1 declares no floating-point to_chars or from_chars; libstdc++ does.
// The portable versions follow their rules with snprintf and strtod, both correctly rounded in
// glibc and in emscripten's C library (musl). They are built everywhere, so that a native test
// compares them with std::to_chars and std::from_chars.
namespace detail {

namespace {

// Digits d1 d2 ... dn and exponent e of a decimal d1.d2...dn x 10^e.
struct Decimal {
  std::string digits;
  int exponent = 0;
};

Decimal decimalOf(const char* text) {  // "%.Ne" output, sign dropped
  Decimal d;
  const char* p = text;
  if (*p == '-')
    ++p;
  for (; *p != 'e'; ++p)
    if (*p != '.')
      d.digits += *p;
  d.exponent = std::atoi(p + 1);
  return d;
}

double valueOf(const Decimal& d, bool negative) {
  std::string text = negative ? "-" : "";
  text += d.digits[0];
  if (d.digits.size() > 1) {
    text += '.';
    text.append(d.digits, 1);
  }
  text += 'e';
  text += std::to_string(d.exponent);
  return std::strtod(text.c_str(), nullptr);
}

// The decimal one unit of its last digit away (up: +1, else -1), as many digits.
Decimal stepped(Decimal d, bool up) {
  std::string& s = d.digits;
  std::size_t i = s.size();
  while (i-- > 0) {
    if (up ? s[i] != '9' : s[i] != '0') {
      s[i] = static_cast<char>(s[i] + (up ? 1 : -1));
      break;
    }
    s[i] = up ? '0' : '9';
  }
  if (up && i == static_cast<std::size_t>(-1)) {  // 99..9 + 1 = 100..0: one more power of ten
    s.insert(s.begin(), '1');
    s.pop_back();
    ++d.exponent;
  } else if (!up && s[0] == '0') {  // 10..0 - 1 = 09..9: one less
    s.erase(s.begin());
    s.push_back('9');
    --d.exponent;
  }
  return d;
}

// The shortest digits that read back as `value` (finite, not zero), the nearest to it among
// those: as std::to_chars chooses them. At each length the correctly rounded digits come
// first; where they miss (the value lies near the edge of its rounding interval, as powers of
// two do), the digits one unit away towards the value may still read back.
Decimal shortestDecimal(double value) {
  const bool negative = std::signbit(value);
  std::array<char, 64> buffer{};
  for (int precision = 0; precision <= 16; ++precision) {
    std::snprintf(buffer.data(), buffer.size(), "%.*e", precision, value);
    const Decimal rounded = decimalOf(buffer.data());
    const double got = std::strtod(buffer.data(), nullptr);
    if (got == value)
      return rounded;
    const Decimal other = stepped(rounded, (got < value) != negative);
    if (valueOf(other, negative) == value)
      return other;
  }
  return decimalOf(buffer.data());  // 17 digits always read back
}

}  // namespace

std::string shortestTextPortable(double value) {
  std::string sign = std::signbit(value) ? "-" : "";
  if (std::isnan(value))
    return sign.append("nan");
  if (std::isinf(value))
    return sign.append("inf");
  if (value == 0.0)
    return sign.append("0");
  const Decimal shortest = shortestDecimal(value);
  const std::string& digits = shortest.digits;
  const int exponent = shortest.exponent;
  // Scientific: d[.ddd]e±XX, at least two exponent digits. (Built by appending: GCC 12 warns
  // falsely about overlapping copies in `"." + digits.substr(1)`.)
  std::string scientific(1, digits[0]);
  if (digits.size() > 1) {
    scientific += '.';
    scientific.append(digits, 1);
  }
  const int magnitude = std::abs(exponent);
  scientific += exponent < 0 ? "e-" : "e+";
  if (magnitude < 10)
    scientific += '0';
  scientific += std::to_string(magnitude);
  // Fixed: the same digits with the point placed, zeros added where needed.
  std::string fixed;
  const auto count = static_cast<int>(digits.size());
  if (exponent < 0) {
    fixed = "0.";
    fixed.append(static_cast<std::size_t>(-exponent - 1), '0');
    fixed += digits;
  } else if (count <= exponent + 1) {
    // A whole number: printf's %f writes every digit of its exact value, not zeros after the
    // shortest digits (5.169596981916737e20 is 516959698191673720832 in fixed notation).
    std::array<char, 400> whole{};
    std::snprintf(whole.data(), whole.size(), "%.0f", std::fabs(value));
    fixed = whole.data();
  } else {
    fixed.assign(digits, 0, static_cast<std::size_t>(exponent + 1));
    fixed += '.';
    fixed.append(digits, static_cast<std::size_t>(exponent + 1));
  }
  // The shorter; fixed on a tie.
  return sign.append(fixed.size() <= scientific.size() ? fixed : scientific);
}

DoubleText readDoubleTextPortable(const char* first, const char* last) {
  // The extent of the number: what from_chars would read, no more (strtod would also take
  // leading blanks, a '+' and hexadecimal).
  const char* p = first;
  const auto at = [&](const char* q) { return q < last ? *q : '\0'; };
  const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  const auto matchWord = [&](const char* q, const char* word) {
    const std::size_t n = std::strlen(word);
    if (static_cast<std::size_t>(last - q) < n)
      return false;
    for (std::size_t i = 0; i < n; ++i)
      if ((q[i] | 0x20) != word[i])
        return false;
    return true;
  };
  if (at(p) == '-')
    ++p;
  const char* end = nullptr;
  if (matchWord(p, "infinity")) {
    end = p + 8;
  } else if (matchWord(p, "inf")) {
    end = p + 3;
  } else if (matchWord(p, "nan")) {
    end = p + 3;
    if (at(end) == '(') {  // nan(n-char-sequence)
      const char* q = end + 1;
      const auto isLetter = [](char c) { return (c | 0x20) >= 'a' && (c | 0x20) <= 'z'; };
      while (q < last && (isDigit(*q) || isLetter(*q) || *q == '_'))
        ++q;
      if (at(q) == ')')
        end = q + 1;
    }
  } else {
    const char* q = p;
    bool anyDigit = false;
    while (isDigit(at(q))) {
      ++q;
      anyDigit = true;
    }
    if (at(q) == '.') {
      ++q;
      while (isDigit(at(q))) {
        ++q;
        anyDigit = true;
      }
    }
    if (!anyDigit)
      return {first, std::errc::invalid_argument, 0.0};
    end = q;
    if ((at(q) | 0x20) == 'e') {
      const char* e = q + 1;
      if (at(e) == '+' || at(e) == '-')
        ++e;
      if (isDigit(at(e))) {
        while (isDigit(at(e)))
          ++e;
        end = e;
      }
    }
  }
  if (end == nullptr)
    return {first, std::errc::invalid_argument, 0.0};
  const std::string text(first, end);
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && (std::isinf(value) || value == 0.0))
    return {end, std::errc::result_out_of_range, 0.0};
  return {end, std::errc{}, value};
}

}  // namespace detail

#if defined(__EMSCRIPTEN__)

std::string shortestText(double value) {
  return detail::shortestTextPortable(value);
}

DoubleText readDoubleText(const char* first, const char* last) {
  return detail::readDoubleTextPortable(first, last);
}

#else

std::string shortestText(double value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

DoubleText readDoubleText(const char* first, const char* last) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(first, last, value);
  return {end, error, value};
}

#endif

}  // namespace recode::io
