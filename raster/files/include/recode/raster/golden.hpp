#pragma once
// Golden vectors: a command stream plus the depth and stencil buffers it must produce,
// stored as JSON (format "recode-golden-1", described in docs/rasterization.md, section 8)
// so that any back end, in any language, can replay and compare them.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "recode/json/error.hpp"
#include "recode/raster/command_stream.hpp"

namespace recode::raster {

// A malformed, unreadable or unwritable command-stream or golden file. The message names the
// source and the JSON path of the problem in the notation of scene files, e.g.
// "case.json: commands[3].func: unknown compare function "LESSER"" ("(root)" for the top
// level); malformed JSON reads "case.json:<line>:<column>: invalid JSON: ...".
class FormatError : public recode::json::JsonError {
 public:
  using recode::json::JsonError::JsonError;
  explicit FormatError(const recode::json::JsonError& error) : recode::json::JsonError(error) {}
};

struct GoldenVector {
  std::string description;
  CommandStream stream;
  // Whole framebuffer, row-major, bottom row (y = 0) first.
  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> stencil;
};

[[nodiscard]] std::string commandStreamToJson(const CommandStream& stream);
[[nodiscard]] CommandStream commandStreamFromJson(std::string_view text, std::string_view source);

// How a golden file is laid out; the document is the same either way. Indented: one value per
// line (the hand-made vectors of data/golden/). Rows: keys in the order of
// docs/rasterization.md, one command and one buffer row per line (the conformance kit's
// vectors: a 16384-pixel row stays one line, and a file a fraction of the size).
enum class GoldenLayout { Indented, Rows };

[[nodiscard]] std::string goldenToJson(const GoldenVector& golden,
                                       GoldenLayout layout = GoldenLayout::Indented);
[[nodiscard]] GoldenVector goldenFromJson(std::string_view text, std::string_view source);

[[nodiscard]] GoldenVector readGolden(const std::filesystem::path& path);

// Reads either format, chosen by the document's "format" key. For a recode-commands-1 file
// the result has empty expected buffers and hasExpected is false.
struct CommandFile {
  GoldenVector content;
  bool hasExpected = false;
};
[[nodiscard]] CommandFile readCommandFile(const std::filesystem::path& path);
void writeGolden(const std::filesystem::path& path, const GoldenVector& golden,
                 GoldenLayout layout = GoldenLayout::Indented);

}  // namespace recode::raster
