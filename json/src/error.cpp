#include "recode/json/error.hpp"

namespace recode::json {

JsonError::JsonError(const std::string& file, const std::string& jsonPath,
                     const std::string& problem)
    : std::runtime_error(file + ": " + (jsonPath.empty() ? "" : jsonPath + ": ") + problem),
      file_(file),
      jsonPath_(jsonPath) {}

JsonError::JsonError(const std::string& file, int line, int column, const std::string& problem)
    : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                         problem),
      file_(file),
      line_(line),
      column_(column) {}

}  // namespace recode::json
