#pragma once
// The JSON reading layer: parsing with line:column, typed readers with JSON paths. Every
// problem throws JsonError (recode/json/error.hpp) naming the file and the JSON path.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "recode/json/error.hpp"

namespace recode::json {

// A JSON path as shown in messages: "(root)" for the top level, else the path itself.
[[nodiscard]] std::string displayJsonPath(const std::string& path);

// path.key, or path["key"] (JSON-escaped) when the key is not a plain identifier; the
// top-level path is "".
[[nodiscard]] std::string childPath(const std::string& path, const std::string& key);
// path[index].
[[nodiscard]] std::string childPath(const std::string& path, std::size_t index);

// A value as compact JSON text, for messages.
[[nodiscard]] std::string jsonText(const nlohmann::json& value);

// A number for messages, short: printf's %.6g ("1e+308", "0.001", "123457"), never 309 digits.
[[nodiscard]] std::string shortNumber(double value);

// What a value is, for "expected ..., got <what>": "null", "true", "a string", "an array",
// "an object", or the number itself.
[[nodiscard]] std::string describeJsonValue(const nlohmann::json& value);

// The deepest nesting of arrays and objects a document may have. A scene's deepest legitimate
// nesting (32 levels of children, two each, under a few levels of file structure) is about 70;
// refusing more keeps a hostile file from costing time and memory that grow with its depth.
inline constexpr std::size_t kMaxJsonDepth = 128;

// Parses JSON text into a document. Malformed JSON throws
// JsonError(sourceName, line, column, "invalid JSON: ...") pointing at the offending
// character (or at the start of the offending string or number); a key repeated within one
// object throws JsonError(sourceName, <path of the repeated key>, "duplicate key").
[[nodiscard]] nlohmann::json parseJsonDocument(std::string_view text,
                                               const std::string& sourceName);

// Typed readers for the fields of a parsed document. `path` is the JSON path of the value
// being read ("" for the top level); every problem throws
// JsonError(sourceName, displayJsonPath(path), problem).
class JsonFieldReader {
 public:
  explicit JsonFieldReader(std::string sourceName) : sourceName_(std::move(sourceName)) {}

  [[nodiscard]] const std::string& sourceName() const { return sourceName_; }

  // Throws the error for the value at `path`.
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;

  // The value is an object.
  void requireObject(const nlohmann::json& value, const std::string& path) const;

  // Every key of the object is one of `allowed`; otherwise the first other key is reported
  // as "unknown key<context> (allowed: ...)".
  void requireOnlyKeys(const nlohmann::json& object, const std::string& path,
                       std::initializer_list<std::string_view> allowed,
                       const std::string& context = "") const;

  [[nodiscard]] double finiteNumber(const nlohmann::json& value, const std::string& path) const;
  [[nodiscard]] double positiveNumber(const nlohmann::json& value, const std::string& path) const;
  // A finite number (finiteNumber's messages) in lo..hi, else "expected a number in
  // -1e+06..1e+06 (<why>), got 1e+160": the range and the rule behind it.
  [[nodiscard]] double numberInRange(const nlohmann::json& value, const std::string& path,
                                     double lo, double hi, std::string_view why) const;
  // A positive number (positiveNumber's messages) up to hi, else "expected a positive number up
  // to 1e+09 (<why>), got 1e+308".
  [[nodiscard]] double positiveNumberUpTo(const nlohmann::json& value, const std::string& path,
                                          double hi, std::string_view why) const;
  // An integer in lo..hi.
  [[nodiscard]] std::int64_t integerInRange(const nlohmann::json& value, const std::string& path,
                                            std::int64_t lo, std::int64_t hi) const;
  // The member `key` of the object at `path`; "missing key" names it when absent.
  [[nodiscard]] const nlohmann::json& member(const nlohmann::json& object, const std::string& path,
                                             std::string_view key) const;
  [[nodiscard]] std::string string(const nlohmann::json& value, const std::string& path) const;
  [[nodiscard]] std::string nonEmptyString(const nlohmann::json& value,
                                           const std::string& path) const;
  // An array of exactly `size` elements (returned as is); `what` describes the expected
  // elements, e.g. "3 numbers [x, y, z]".
  const nlohmann::json& arrayOfSize(const nlohmann::json& value, const std::string& path,
                                    std::size_t size, const char* what) const;

 private:
  std::string sourceName_;
};

}  // namespace recode::json
