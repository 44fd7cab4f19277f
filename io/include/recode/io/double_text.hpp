#pragma once
// Doubles to and from text by the rules of std::to_chars and std::from_chars (the shortest text
// that reads back as the same double; a whole number token read with correct rounding), also
// where the standard library lacks their floating-point overloads: emscripten's libc++, for the
// WebAssembly build (wasm/), which must read scene and mesh files to the same bits.

#include <string>
#include <system_error>

namespace recode::io {

// std::to_chars(first, last, value) for a double: "0.1", "-2", "1e-300", "nan", "-inf".
[[nodiscard]] std::string shortestText(double value);

struct DoubleText {
  const char* end;  // one past the last character read
  std::errc error;  // {}, std::errc::invalid_argument or std::errc::result_out_of_range
  double value;     // the number read; unchanged (0) on invalid_argument
};

// std::from_chars(first, last, value) for a double in the general format: an optional '-',
// then digits with an optional point and exponent, or inf, infinity, nan (any case).
[[nodiscard]] DoubleText readDoubleText(const char* first, const char* last);

// The versions built from snprintf and strtod that the two above are where the standard
// library lacks the floating-point overloads; public so that a test can compare them with the
// standard library's where it has them.
namespace detail {
[[nodiscard]] std::string shortestTextPortable(double value);
[[nodiscard]] DoubleText readDoubleTextPortable(const char* first, const char* last);
}  // namespace detail

}  // namespace recode::io
