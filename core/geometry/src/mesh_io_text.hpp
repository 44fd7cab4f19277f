#pragma once
// Internal to the mesh readers (not installed, not public API): the error, line and token
// helpers that the OFF reader (mesh_io_off.cpp), the OBJ line check (mesh_io_obj.cpp), the ASCII
// STL reader (mesh_io_stl.cpp) and the PLY header check (mesh_io_ply.cpp) share, so that both read
// numbers and word their messages the same way. The per-token helpers are inline because they run
// once per token of a possibly large file; the message builders are defined in mesh_io.cpp.

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/io/double_text.hpp"

namespace recode::core::detail {

// The most vertices a mesh may have, so that every index fits a VertexIndex.
inline constexpr std::size_t kMaxVertices = std::numeric_limits<VertexIndex>::max();

// Throw MeshError("<path>: <problem>") and MeshError("<path>:<line>: <problem>").
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem);
[[noreturn]] void failAt(const std::filesystem::path& path, std::size_t line,
                         const std::string& problem);

// Calls visit(lineText, lineNumber) for each line (1-based). Lines end at "\n", "\r" or
// "\r\n", as tinyobjloader counts them; the terminator is not part of the text. Returns
// the number of lines.
template <typename Visit>
std::size_t forEachLine(std::string_view text, Visit&& visit) {
  std::size_t number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = pos;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') {
      ++end;
    }
    ++number;
    visit(text.substr(pos, end - pos), number);
    if (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') {
      ++end;
    }
    pos = end + 1;
  }
  return number;
}

inline bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\f' || c == '\v';
}

inline std::vector<std::string_view> tokenize(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && isBlank(line[pos])) {
      ++pos;
    }
    const std::size_t start = pos;
    while (pos < line.size() && !isBlank(line[pos])) {
      ++pos;
    }
    if (pos > start) {
      tokens.push_back(line.substr(start, pos - start));
    }
  }
  return tokens;
}

// The whole token must be a number (a leading '+' is allowed); "nan" and "inf" parse.
inline std::optional<double> parseDouble(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') {
    token.remove_prefix(1);
  }
  const char* end = token.data() + token.size();
  const auto [ptr, ec, value] = io::readDoubleText(token.data(), end);
  if (ptr != end) {
    return std::nullopt;
  }
  if (ec == std::errc::result_out_of_range) {
    // A well-formed number beyond double's range: strtod gives +-HUGE_VAL (infinity) for
    // overflow, which the caller rejects as non-finite, and 0 or a subnormal for underflow.
    const std::string copy(token);
    return std::strtod(copy.c_str(), nullptr);
  }
  if (ec != std::errc()) {
    return std::nullopt;
  }
  return value;
}

inline std::optional<long long> parseInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') {
    token.remove_prefix(1);
  }
  long long value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end) {
    return std::nullopt;
  }
  return value;
}

// A token as messages show it: quoted, control characters escaped (recode::io::printable), and
// cut short so that a garbage line stays readable.
std::string quote(std::string_view token);

// Parses three coordinate tokens; on error returns the problem text.
inline std::optional<std::string> parseCoordinates(const std::vector<std::string_view>& tokens,
                                                   std::size_t first, Eigen::Vector3d& out) {
  for (int axis = 0; axis < 3; ++axis) {
    const std::string_view token = tokens[first + static_cast<std::size_t>(axis)];
    const std::optional<double> value = parseDouble(token);
    if (!value) {
      return "invalid coordinate " + quote(token);
    }
    if (!std::isfinite(*value)) {
      return "non-finite coordinate " + quote(token);
    }
    out[axis] = *value;
  }
  return std::nullopt;
}

// "face index <index> out of range (<vertexCount> vertices)".
std::string outOfRange(long long index, std::size_t vertexCount);

// Appends the fan triangulation of a polygon (indices already validated).
inline void appendFan(std::vector<Triangle>& triangles, const std::vector<VertexIndex>& polygon) {
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
  }
}

// The readers, given the file's whole contents; path is for messages only.
TriangleMesh parseOff(const std::filesystem::path& path, std::string_view text);
TriangleMesh parseStl(const std::filesystem::path& path, std::string_view data);
TriangleMesh parsePly(const std::filesystem::path& path, std::string_view data);
TriangleMesh parseObj(const std::filesystem::path& path, const std::string& text);
std::vector<MeshGroup> parseObjGroups(const std::filesystem::path& path, const std::string& text);

}  // namespace recode::core::detail
