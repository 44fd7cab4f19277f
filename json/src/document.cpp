// JSON reading layer: text -> document with positions and no duplicate keys; typed field readers.
#include "recode/json/document.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace recode::json {

using nlohmann::json;

std::string displayJsonPath(const std::string& path) {
  return path.empty() ? "(root)" : path;
}

// Invalid UTF-8, which the parser does not let through anyway, would be replaced rather than
// throw.
std::string jsonText(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string childPath(const std::string& path, const std::string& key) {
  const bool identifier = !key.empty() && !(key[0] >= '0' && key[0] <= '9') &&
                          std::all_of(key.begin(), key.end(), [](char c) {
                            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                                   (c >= '0' && c <= '9') || c == '_';
                          });
  if (!identifier)
    return path + "[" + jsonText(json(key)) + "]";
  return path.empty() ? key : path + "." + key;
}

std::string childPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string describeJsonValue(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return jsonText(value);
    default:
      return "a binary value";
  }
}

// ---- JSON text -> document ------------------------------------------------------------

namespace {

// Builds the document from nlohmann's SAX events, so that (unlike json::parse) a repeated
// key is an error instead of silently keeping the last value, and the byte position of a
// syntax error or a number that overflows a double is known.
class DocumentBuilder : public nlohmann::json_sax<json> {
 public:
  bool null() override { return add(json(nullptr)); }
  bool boolean(bool value) override { return add(json(value)); }
  bool number_integer(number_integer_t value) override { return add(json(value)); }
  bool number_unsigned(number_unsigned_t value) override { return add(json(value)); }
  bool number_float(number_float_t value, const string_t& /*text*/) override {
    return add(json(value));
  }
  bool string(string_t& value) override { return add(json(std::move(value))); }
  bool binary(binary_t& value) override { return add(json::binary(std::move(value))); }
  bool start_object(std::size_t /*elements*/) override { return open(json::object()); }
  bool end_object() override {
    open_.pop_back();
    return true;
  }
  bool start_array(std::size_t /*elements*/) override { return open(json::array()); }
  bool end_array() override {
    open_.pop_back();
    return true;
  }
  bool key(string_t& name) override {
    const Container& parent = open_.back();
    if (parent.value->contains(name)) {
      duplicatePath_ = childPath(parent.path, name);
      return false;
    }
    key_ = name;
    return true;
  }
  bool parse_error(std::size_t position, const std::string& lastToken,
                   const nlohmann::detail::exception& error) override {
    errorPosition_ = position;
    errorToken_ = lastToken;
    errorMessage_ = error.what();
    return false;
  }

  [[nodiscard]] json& document() { return root_; }
  [[nodiscard]] const std::optional<std::string>& duplicatePath() const { return duplicatePath_; }
  [[nodiscard]] bool tooDeep() const { return tooDeep_; }
  [[nodiscard]] std::size_t errorPosition() const { return errorPosition_; }
  [[nodiscard]] const std::string& errorToken() const { return errorToken_; }
  [[nodiscard]] const std::string& errorMessage() const { return errorMessage_; }

 private:
  struct Container {
    json* value;
    std::string path;
  };

  // Places a value in the innermost open container (or as the document) and returns it.
  json* place(json value, std::string* path) {
    if (open_.empty()) {
      root_ = std::move(value);
      *path = "";
      return &root_;
    }
    Container& parent = open_.back();
    if (parent.value->is_array()) {
      *path = childPath(parent.path, parent.value->size());
      parent.value->push_back(std::move(value));
      return &parent.value->back();
    }
    *path = childPath(parent.path, key_);
    json& slot = (*parent.value)[key_];
    slot = std::move(value);
    return &slot;
  }
  bool add(json value) {
    std::string path;
    place(std::move(value), &path);
    return true;
  }
  bool open(json container) {
    // Refused before the container is placed: each open container keeps its path, so the cost
    // of a document grows with the square of its depth.
    if (open_.size() >= kMaxJsonDepth) {
      tooDeep_ = true;
      return false;
    }
    std::string path;
    json* placed = place(std::move(container), &path);
    open_.push_back({placed, std::move(path)});
    return true;
  }

  json root_;
  std::vector<Container> open_;
  std::string key_;
  std::optional<std::string> duplicatePath_;
  bool tooDeep_ = false;
  std::size_t errorPosition_ = 0;
  std::string errorToken_;
  std::string errorMessage_;
};

// nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: syntax
// error ..." without the exception id and its own position (ours is printed instead).
std::string plainParseMessage(std::string message) {
  if (!message.empty() && message.front() == '[') {
    const std::size_t close = message.find("] ");
    if (close != std::string::npos)
      message.erase(0, close + 2);
  }
  const std::string prefix = "parse error";
  if (message.starts_with(prefix)) {
    const std::size_t colon = message.find(": ");
    if (colon != std::string::npos)
      message.erase(0, colon + 2);
  }
  return message;
}

// nlohmann's "last token" is only the token itself for strings and numbers (for other
// tokens it may still hold the text since the last string or number): true for a string
// token ('"', anything without an unescaped '"', then at most a closing '"') or a number.
bool isStringOrNumberToken(const std::string& token) {
  if (token.empty())
    return false;
  if (token.front() == '"') {
    for (std::size_t i = 1; i < token.size(); ++i) {
      if (token[i] == '\\')
        ++i;
      else if (token[i] == '"')
        return i + 1 == token.size();
    }
    return true;
  }
  return (token.front() == '-' || (token.front() >= '0' && token.front() <= '9')) &&
         token.find_first_not_of("0123456789+-.eE") == std::string::npos;
}

}  // namespace

json parseJsonDocument(std::string_view text, const std::string& sourceName) {
  DocumentBuilder builder;
  const bool ok = json::sax_parse(text.begin(), text.end(), &builder);
  if (ok)
    return std::move(builder.document());
  if (builder.duplicatePath())
    throw JsonError(sourceName, *builder.duplicatePath(), "duplicate key");
  if (builder.tooDeep()) {
    throw JsonError(
        sourceName, "",
        "arrays and objects nested more than " + std::to_string(kMaxJsonDepth) + " deep");
  }
  // nlohmann's position counts the characters read, up to the last one it looked at (one
  // more when it read the end of input). Point there, or at the first character of the
  // offending string or number when nlohmann reports one that ends at that position.
  const std::size_t end = std::min(builder.errorPosition(), text.size() + 1);
  std::size_t offending = end > 0 ? end - 1 : 0;
  const std::string& token = builder.errorToken();
  if (isStringOrNumberToken(token) && token.size() <= end && end <= text.size() &&
      text.substr(end - token.size(), token.size()) == token) {
    offending = end - token.size();
  }
  offending = std::min(offending, text.size());
  const std::string_view before = text.substr(0, offending);
  const std::size_t lastNewline = before.rfind('\n');
  const std::size_t lineStart = lastNewline == std::string_view::npos ? 0 : lastNewline + 1;
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t column = offending - lineStart + 1;
  throw JsonError(sourceName, static_cast<int>(std::min<std::ptrdiff_t>(line, INT_MAX)),
                  static_cast<int>(std::min<std::size_t>(column, INT_MAX)),
                  "invalid JSON: " + plainParseMessage(builder.errorMessage()));
}

// ---- document -> typed values ---------------------------------------------------------

void JsonFieldReader::fail(const std::string& path, const std::string& problem) const {
  throw JsonError(sourceName_, displayJsonPath(path), problem);
}

void JsonFieldReader::requireObject(const json& value, const std::string& path) const {
  if (!value.is_object())
    fail(path, "expected an object, got " + describeJsonValue(value));
}

void JsonFieldReader::requireOnlyKeys(const json& object, const std::string& path,
                                      std::initializer_list<std::string_view> allowed,
                                      const std::string& context) const {
  for (const auto& [key, value] : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end())
      continue;
    std::string list;
    for (std::string_view a : allowed)
      list += (list.empty() ? "" : ", ") + std::string(a);
    fail(childPath(path, key), "unknown key" + context + " (allowed: " + list + ")");
  }
}

double JsonFieldReader::finiteNumber(const json& value, const std::string& path) const {
  if (!value.is_number())
    fail(path, "expected a number, got " + describeJsonValue(value));
  const double x = value.get<double>();
  if (!std::isfinite(x))
    fail(path, "expected a finite number, got " + jsonText(value));
  return x;
}

double JsonFieldReader::positiveNumber(const json& value, const std::string& path) const {
  if (!value.is_number())
    fail(path, "expected a positive number, got " + describeJsonValue(value));
  const double x = finiteNumber(value, path);
  if (!(x > 0.0))
    fail(path, "expected a positive number, got " + jsonText(value));
  return x;
}

double JsonFieldReader::numberInRange(const json& value, const std::string& path, double lo,
                                      double hi, std::string_view why) const {
  const double x = finiteNumber(value, path);
  if (!(x >= lo && x <= hi)) {
    fail(path, "expected a number in " + shortNumber(lo) + ".." + shortNumber(hi) + " (" +
                   std::string(why) + "), got " + jsonText(value));
  }
  return x;
}

double JsonFieldReader::positiveNumberUpTo(const json& value, const std::string& path, double hi,
                                           std::string_view why) const {
  const double x = positiveNumber(value, path);
  if (!(x <= hi)) {
    fail(path, "expected a positive number up to " + shortNumber(hi) + " (" + std::string(why) +
                   "), got " + jsonText(value));
  }
  return x;
}

std::int64_t JsonFieldReader::integerInRange(const json& value, const std::string& path,
                                             std::int64_t lo, std::int64_t hi) const {
  const std::string range = "an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
  if (!value.is_number_integer())
    fail(path, "expected " + range + ", got " + describeJsonValue(value));
  if (value.is_number_unsigned()) {
    const std::uint64_t u = value.get<std::uint64_t>();
    if ((lo > 0 && u < static_cast<std::uint64_t>(lo)) || u > static_cast<std::uint64_t>(hi))
      fail(path, "expected " + range + ", got " + jsonText(value));
    return static_cast<std::int64_t>(u);
  }
  const std::int64_t x = value.get<std::int64_t>();
  if (x < lo || x > hi)
    fail(path, "expected " + range + ", got " + jsonText(value));
  return x;
}

const json& JsonFieldReader::member(const json& object, const std::string& path,
                                    std::string_view key) const {
  requireObject(object, path);
  const auto found = object.find(key);
  if (found == object.end())
    fail(path, "missing key \"" + std::string(key) + "\"");
  return *found;
}

std::string JsonFieldReader::string(const json& value, const std::string& path) const {
  if (!value.is_string())
    fail(path, "expected a string, got " + describeJsonValue(value));
  return value.get<std::string>();
}

std::string JsonFieldReader::nonEmptyString(const json& value, const std::string& path) const {
  std::string s = string(value, path);
  if (s.empty())
    fail(path, "expected a non-empty string, got \"\"");
  return s;
}

const json& JsonFieldReader::arrayOfSize(const json& value, const std::string& path,
                                         std::size_t size, const char* what) const {
  if (!value.is_array())
    fail(path, std::string("expected an array of ") + what + ", got " + describeJsonValue(value));
  if (value.size() != size) {
    fail(path, std::string("expected an array of ") + what + ", got " +
                   std::to_string(value.size()) + " element" + (value.size() == 1 ? "" : "s"));
  }
  return value;
}

}  // namespace recode::json
