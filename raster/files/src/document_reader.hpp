#pragma once
// Reads golden vectors and command streams from parsed JSON (docs/rasterization.md, section 8);
// golden.cpp reads the documents with it, command_reader.cpp the commands.

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "recode/json/document.hpp"
#include "recode/raster/golden.hpp"

namespace recode::raster::files {

using nlohmann::json;
using recode::json::childPath;

// Walks a parsed document, remembering the JSON path of every value it reads so that each
// error names where it is. What is read and checked is the layer's (recode::json); the file
// formats add their own rules (names of enumerations, buffer shapes, the format string).
class Reader {
 public:
  explicit Reader(std::string_view source) : fields_(std::string(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    fields_.fail(path, problem);
  }

  // The typed reads are the JSON reading layer's, so golden and command-stream files word their
  // problems as scene files do.
  const json& member(const json& obj, const std::string& path, const char* key) const {
    return fields_.member(obj, path, key);
  }

  void requireObject(const json& value, const std::string& path) const {
    fields_.requireObject(value, path);
  }

  void onlyKeys(const json& obj, const std::string& path,
                std::initializer_list<std::string_view> allowed) const {
    fields_.requireObject(obj, path);
    fields_.requireOnlyKeys(obj, path, allowed);
  }

  std::int64_t integer(const json& v, const std::string& path, std::int64_t lo,
                       std::int64_t hi) const {
    return fields_.integerInRange(v, path, lo, hi);
  }

  double number(const json& v, const std::string& path) const {
    return fields_.finiteNumber(v, path);
  }

  std::string string(const json& v, const std::string& path) const {
    return fields_.string(v, path);
  }

  template <class Enum>
  Enum name(const json& v, const std::string& path, std::optional<Enum> (*parse)(std::string_view),
            const char* what) const {
    const std::string s = string(v, path);
    const auto parsed = parse(s);
    if (!parsed)
      fail(path, std::string("unknown ") + what + " \"" + s + "\"");
    return *parsed;
  }

  std::uint8_t byte(const json& v, const std::string& path) const {
    return static_cast<std::uint8_t>(integer(v, path, 0, 255));
  }

  // The command at `path` (commands[i]), refused with the path of its first wrong field.
  Command command(const json& c, const std::string& path) const;
  cmd::Draw draw(const json& c, const std::string& path) const;
  // The width, height and commands of a command stream or golden vector.
  CommandStream stream(const json& doc) const;

  template <class T>
  std::vector<T> buffer(const json& v, const std::string& path, int width, int height,
                        std::int64_t maxValue) const {
    if (!v.is_array() || v.size() != static_cast<std::size_t>(height)) {
      fail(path, "expected " + std::to_string(height) + " rows");
    }
    std::vector<T> out;
    out.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < v.size(); ++y) {
      const std::string rp = childPath(path, y);
      if (!v[y].is_array() || v[y].size() != static_cast<std::size_t>(width)) {
        fail(rp, "expected a row of " + std::to_string(width) + " values");
      }
      for (std::size_t x = 0; x < v[y].size(); ++x) {
        out.push_back(static_cast<T>(integer(v[y][x], childPath(rp, x), 0, maxValue)));
      }
    }
    return out;
  }

  void format(const json& doc, std::string_view expected) const {
    const std::string f = string(member(doc, "", "format"), "format");
    if (f != expected)
      fail("format", "expected \"" + std::string(expected) + "\", got \"" + f + "\"");
  }

 private:
  recode::json::JsonFieldReader fields_;
};

}  // namespace recode::raster::files
