#pragma once
// A JSON object written to a stream piece by piece, one element of its array at a time, in
// exactly the bytes nlohmann::ordered_json::dump(2) would give for the whole object: `recode
// run --json` prints each frame as it is done instead of holding the run's frames, so memory
// follows the largest frame, not the run (docs/cli.md).

#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

namespace recode::app {

class StreamedJsonObject {
 public:
  // Writes `head`'s members (an object; may be empty), then opens the array `arrayKey`.
  StreamedJsonObject(std::ostream& out, const nlohmann::ordered_json& head, std::string arrayKey);

  // Appends one element to the array.
  void add(const nlohmann::ordered_json& element);

  // Closes the array, writes `tail`'s members (an object; may be empty) after it, closes the
  // object and ends the line.
  void finish(const nlohmann::ordered_json& tail);

 private:
  std::ostream& out_;
  bool anyElement_ = false;
};

}  // namespace recode::app
