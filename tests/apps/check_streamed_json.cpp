// StreamedJsonObject (apps/streamed_json.hpp) writes, piece by piece, the bytes that dumping the
// whole object with ordered_json::dump(2) gives: `recode run --json` relies on it to print a
// run frame by frame with the output of a run held whole. Checked on documents with every kind
// of member: empty and nested arrays and objects, escaped and non-ASCII strings, numbers, an
// empty head, an empty tail and no elements.
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/streamed_json.hpp"

using nlohmann::ordered_json;

namespace {

struct Document {
  ordered_json head, tail;
  std::vector<ordered_json> elements;
};

std::string whole(const Document& d, const std::string& key) {
  ordered_json j = d.head.is_null() ? ordered_json::object() : d.head;
  j[key] = ordered_json::array();
  for (const ordered_json& e : d.elements)
    j[key].push_back(e);
  for (auto it = d.tail.begin(); it != d.tail.end(); ++it)
    j[it.key()] = it.value();
  return j.dump(2) + "\n";
}

std::string streamed(const Document& d, const std::string& key) {
  std::ostringstream out;
  recode::app::StreamedJsonObject s(out, d.head.is_null() ? ordered_json::object() : d.head, key);
  for (const ordered_json& e : d.elements)
    s.add(e);
  s.finish(d.tail.is_null() ? ordered_json::object() : d.tail);
  return out.str();
}

}  // namespace

int main() {
  const ordered_json frame = ordered_json::parse(
      R"({"frame": 3, "contacts": [{"a": "cone \"1\"\n", "box": [[0.5, -1e-300, 2], [1, 2, 3]],
          "empty": [], "none": {}, "nested": {"x": [1, [2, [3, {}]]]}}], "pairs": 12})");
  const ordered_json stats = ordered_json::parse(
      R"({"stats": {"TTF_s": 0.25, "frames": 2, "list": [], "name": "\u00e9\u0001"}, "end": null})");
  const std::vector<Document> documents = {
      {ordered_json::parse(R"({"scene": "s", "objects": [{"n": 1}], "flag": true})"),
       stats,
       {frame, frame, ordered_json::object(), ordered_json::array(), 7, "text"}},
      {ordered_json::parse(R"({"scene": "s"})"), stats, {}},
      {ordered_json::object(), ordered_json::object(), {frame}},
      {ordered_json::object(), ordered_json::object(), {}},
      {ordered_json::parse(R"({"deep": {"a": {"b": {"c": []}}}})"),
       ordered_json::object(),
       {ordered_json::array({ordered_json::array({1, 2}), ordered_json::object()})}},
  };
  int failed = 0;
  for (std::size_t i = 0; i < documents.size(); ++i) {
    const std::string expected = whole(documents[i], "frames");
    const std::string got = streamed(documents[i], "frames");
    if (got != expected) {
      std::cerr << "document " << i << ": streamed bytes differ\n--- dump(2):\n"
                << expected << "--- streamed:\n"
                << got;
      ++failed;
    }
  }
  if (failed) {
    std::cerr << failed << " of " << documents.size() << " documents differ\n";
    return EXIT_FAILURE;
  }
  std::cout << "streamed JSON OK: " << documents.size() << " documents equal dump(2)\n";
  return EXIT_SUCCESS;
}
