#pragma once
// Text from a user's file (an object's name, a token of a mesh line) echoed in a report or an
// error message: its control characters could move the cursor, recolour the terminal or forge a
// line of output, so they are shown escaped instead.

#include <string>
#include <string_view>

namespace recode::io {

// `text` with every ASCII control character (0x00-0x1f, 0x7f) escaped as \n, \r, \t, \\ or
// \xNN ("evil\x1b[31m" stays readable and inert); every other byte, UTF-8 included, is kept.
// A backslash is kept as is, so text without control characters comes back unchanged.
[[nodiscard]] std::string printable(std::string_view text);

}  // namespace recode::io
