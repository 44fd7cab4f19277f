// The "parts" object of a scene file: named geometry, read once and copied for every use.
#include <algorithm>
#include <string>
#include <vector>

#include "scene_reader.hpp"

namespace recode::core::detail {

using recode::json::describeJsonValue;
using recode::json::jsonText;

PartTable::PartTable(const JsonFieldReader& fields, const json* parts)
    : fields_(fields), parts_(parts) {
  if (parts_ && !parts_->is_object())
    fields_.fail("parts", "expected an object of named parts, got " + describeJsonValue(*parts_));
}

bool PartTable::defines(const std::string& name) const {
  return parts_ && parts_->contains(name);
}

std::string PartTable::names() const {
  std::string names;
  for (const std::string& name : list())
    names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none defined" : names;
}

const json& PartTable::definition(const std::string& name) const {
  return parts_->at(name);
}

std::vector<std::string> PartTable::list() const {
  std::vector<std::string> names;
  if (parts_) {
    for (const auto& [name, value] : parts_->items())
      names.push_back(name);
  }
  return names;
}

const PartTable::Done* PartTable::done(const std::string& name) const {
  const auto it = done_.find(name);
  return it == done_.end() ? nullptr : &it->second;
}

void PartTable::enter(const std::string& name, const std::string& usePath) {
  const auto open = std::find(expanding_.begin(), expanding_.end(), name);
  if (open != expanding_.end()) {
    std::string cycle;
    for (auto it = open; it != expanding_.end(); ++it)
      cycle += *it + " -> ";
    fields_.fail(usePath, "part " + jsonText(json(name)) + " contains itself (" + cycle + name +
                              "); parts must not form a cycle");
  }
  expanding_.push_back(name);
}

void PartTable::leave(const std::string& name, const SceneObject& geometry, long long blocks,
                      std::size_t triangles) {
  expanding_.pop_back();
  done_.emplace(name, Done{geometry, blocks, triangles});
}

}  // namespace recode::core::detail
