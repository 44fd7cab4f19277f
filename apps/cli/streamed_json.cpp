#include "cli/streamed_json.hpp"

#include <stdexcept>
#include <string_view>

namespace recode::app {

namespace {

constexpr int kIndent = 2;

// `value` as dump(2) writes it nested `depth` levels deep: every line after the first indented
// by depth * 2 more spaces (JSON strings hold no raw newline, so lines split cleanly).
void writeNested(std::ostream& out, const nlohmann::ordered_json& value, int depth) {
  const std::string text = value.dump(kIndent);
  const std::string pad(static_cast<std::size_t>(depth * kIndent), ' ');
  std::string_view rest = text;
  for (std::size_t newline = rest.find('\n'); newline != std::string_view::npos;
       newline = rest.find('\n')) {
    out << rest.substr(0, newline + 1) << pad;
    rest.remove_prefix(newline + 1);
  }
  out << rest;
}

// The members of `object` at depth 1, each line but the last followed by ",\n"; returns
// whether any was written.
bool writeMembers(std::ostream& out, const nlohmann::ordered_json& object, bool first) {
  if (!object.is_object())
    throw std::logic_error("StreamedJsonObject: head and tail must be JSON objects");
  for (auto it = object.begin(); it != object.end(); ++it) {
    out << (first ? "" : ",\n") << "  " << nlohmann::ordered_json(it.key()).dump() << ": ";
    writeNested(out, it.value(), 1);
    first = false;
  }
  return !first;
}

}  // namespace

StreamedJsonObject::StreamedJsonObject(std::ostream& out, const nlohmann::ordered_json& head,
                                       std::string arrayKey)
    : out_(out) {
  out_ << "{\n";
  const bool wrote = writeMembers(out_, head, true);
  out_ << (wrote ? ",\n" : "") << "  " << nlohmann::ordered_json(arrayKey).dump() << ": [";
}

void StreamedJsonObject::add(const nlohmann::ordered_json& element) {
  out_ << (anyElement_ ? ",\n    " : "\n    ");
  writeNested(out_, element, 2);
  anyElement_ = true;
}

void StreamedJsonObject::finish(const nlohmann::ordered_json& tail) {
  out_ << (anyElement_ ? "\n  ]" : "]");
  writeMembers(out_, tail, false);
  out_ << "\n}\n";
}

}  // namespace recode::app
