#pragma once
// The one error of the JSON reading layer. Kept apart from document.hpp so that a public
// header can name it (SceneError, raster::FormatError derive from it) without pulling in
// nlohmann.

#include <stdexcept>
#include <string>

namespace recode::json {

// "<file>: <json path>: <problem>", e.g. "pair.json: objects[1].shape.radius: expected a
// positive number, got -2". A problem with the file as a whole has an empty JSON path and
// reads "<file>: <problem>"; malformed JSON reads "<file>:<line>:<column>: invalid JSON: ..."
// (line() and column() are then 1-based, counted in bytes; both are 0 for every other error).
class JsonError : public std::runtime_error {
 public:
  JsonError(const std::string& file, const std::string& jsonPath, const std::string& problem);
  JsonError(const std::string& file, int line, int column, const std::string& problem);
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& jsonPath() const { return jsonPath_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] int column() const { return column_; }

 private:
  std::string file_;
  std::string jsonPath_;
  int line_ = 0;
  int column_ = 0;
};

}  // namespace recode::json
