#pragma once
// What the fuzz targets share: the input as text, and the errors that are the readers' designed
// answer to bad input (every reader reports bad input as std::runtime_error — SceneError,
// FormatError, MeshError, FileReadError — or std::invalid_argument). Anything else escaping a
// reader (a crash, a sanitizer report, std::bad_alloc, std::length_error, a nlohmann exception) is
// a finding.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

namespace recode::fuzz {

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

template <typename F>
void expectCleanErrors(F&& read) {
  try {
    read();
  } catch (const std::runtime_error&) {
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace recode::fuzz
