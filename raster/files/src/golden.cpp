#include "recode/raster/golden.hpp"

#include "recode/raster/fixed_point.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "document_reader.hpp"
#include "recode/io/bounded_read.hpp"
#include "recode/json/document.hpp"

namespace recode::raster {

namespace {

using files::Reader;
using nlohmann::json;

constexpr std::string_view kGoldenFormat = "recode-golden-1";
constexpr std::string_view kStreamFormat = "recode-commands-1";

// ---- writing -------------------------------------------------------------------------

json commandToJson(const Command& command) {
  return std::visit(
      [](const auto& c) -> json {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, cmd::Scissor>) {
          return {{"op", "scissor"}, {"rect", {c.rect.x0, c.rect.y0, c.rect.x1, c.rect.y1}}};
        } else if constexpr (std::is_same_v<T, cmd::ClearDepth>) {
          return {{"op", "clear_depth"}, {"value", c.value}};
        } else if constexpr (std::is_same_v<T, cmd::ClearStencil>) {
          return {{"op", "clear_stencil"}, {"value", c.value}};
        } else if constexpr (std::is_same_v<T, cmd::DepthFunc>) {
          return {{"op", "depth_func"}, {"func", toString(c.func)}};
        } else if constexpr (std::is_same_v<T, cmd::DepthWriteMask>) {
          return {{"op", "depth_write_mask"}, {"write", c.write}};
        } else if constexpr (std::is_same_v<T, cmd::StencilFunc>) {
          return {{"op", "stencil_func"},
                  {"func", toString(c.func)},
                  {"ref", c.ref},
                  {"value_mask", c.valueMask}};
        } else if constexpr (std::is_same_v<T, cmd::StencilOpsCmd>) {
          return {{"op", "stencil_ops"},
                  {"face", toString(c.face)},
                  {"sfail", toString(c.ops.stencilFail)},
                  {"dpfail", toString(c.ops.depthFail)},
                  {"dppass", toString(c.ops.depthPass)}};
        } else if constexpr (std::is_same_v<T, cmd::StencilWriteMask>) {
          return {{"op", "stencil_write_mask"}, {"mask", c.mask}};
        } else if constexpr (std::is_same_v<T, cmd::Cull>) {
          return {{"op", "cull"}, {"mode", toString(c.mode)}};
        } else {
          // Vertices as exact 24.8 fixed-point integers plus the float depth; a float
          // converted to double prints with enough digits to round-trip exactly.
          json vertices = json::array();
          for (const WindowVertex& v : c.vertices) {
            vertices.push_back({snapToFixed(v.x), snapToFixed(v.y), static_cast<double>(v.z)});
          }
          return {{"op", "draw"}, {"vertices_fixed", vertices}, {"indices", c.indices}};
        }
      },
      command);
}

json streamBody(const CommandStream& stream) {
  json commands = json::array();
  for (const Command& c : stream.commands)
    commands.push_back(commandToJson(c));
  return {{"width", stream.width}, {"height", stream.height}, {"commands", commands}};
}

template <class T>
json rows(const std::vector<T>& buffer, int width, int height) {
  json out = json::array();
  for (int y = 0; y < height; ++y) {
    const auto begin = buffer.begin() + static_cast<std::ptrdiff_t>(y) * width;
    out.push_back(std::vector<T>(begin, begin + width));
  }
  return out;
}

// ---- reading -------------------------------------------------------------------------

// Through the layer: malformed JSON and repeated keys are refused there, with line:column
// or the JSON path.
json parseDocument(std::string_view text, std::string_view source) {
  json doc = recode::json::parseJsonDocument(text, std::string(source));
  Reader(source).requireObject(doc, "");
  return doc;
}

GoldenVector readGoldenDocument(const json& doc, std::string_view source) {
  const Reader r(source);
  r.onlyKeys(doc, "", {"format", "description", "width", "height", "commands", "expected"});
  r.format(doc, kGoldenFormat);
  GoldenVector g;
  g.description = r.string(r.member(doc, "", "description"), "description");
  g.stream = r.stream(doc);
  const json& expected = r.member(doc, "", "expected");
  r.onlyKeys(expected, "expected", {"depth", "stencil"});
  g.depth = r.buffer<std::uint32_t>(r.member(expected, "expected", "depth"), "expected.depth",
                                    g.stream.width, g.stream.height, kDepthMax);
  g.stencil = r.buffer<std::uint8_t>(r.member(expected, "expected", "stencil"), "expected.stencil",
                                     g.stream.width, g.stream.height, 255);
  return g;
}

// The layer throws JsonError; callers of this header catch FormatError.
template <class Read>
auto asFormatError(Read read) -> decltype(read()) {
  try {
    return read();
  } catch (const FormatError&) {
    throw;
  } catch (const recode::json::JsonError& e) {
    throw FormatError(e);
  }
}

}  // namespace

std::string commandStreamToJson(const CommandStream& stream) {
  json doc = {{"format", kStreamFormat}};
  doc.update(streamBody(stream));
  return doc.dump(1);
}

CommandStream commandStreamFromJson(std::string_view text, std::string_view source) {
  return asFormatError([&] {
    const json doc = parseDocument(text, source);
    const Reader r(source);
    r.onlyKeys(doc, "", {"format", "width", "height", "commands"});
    r.format(doc, kStreamFormat);
    return r.stream(doc);
  });
}

namespace {

// One element of an array per line, each dumped compactly, under `indent` spaces.
std::string linePerElement(const json& array, const std::string& indent) {
  std::string out = "[\n";
  for (std::size_t i = 0; i < array.size(); ++i) {
    out += indent + " " + array[i].dump() + (i + 1 < array.size() ? ",\n" : "\n");
  }
  return out + indent + "]";
}

std::string goldenRows(const GoldenVector& golden) {
  const json body = streamBody(golden.stream);
  std::string out = "{\n";
  out += " \"format\": " + json(kGoldenFormat).dump() + ",\n";
  out += " \"description\": " + json(golden.description).dump() + ",\n";
  out += " \"width\": " + body["width"].dump() + ",\n";
  out += " \"height\": " + body["height"].dump() + ",\n";
  out += " \"commands\": " + linePerElement(body["commands"], " ") + ",\n";
  out += " \"expected\": {\n";
  out += "  \"depth\": " +
         linePerElement(rows(golden.depth, golden.stream.width, golden.stream.height), "  ") +
         ",\n";
  out += "  \"stencil\": " +
         linePerElement(rows(golden.stencil, golden.stream.width, golden.stream.height), "  ") +
         "\n";
  return out + " }\n}";
}

}  // namespace

std::string goldenToJson(const GoldenVector& golden, GoldenLayout layout) {
  if (layout == GoldenLayout::Rows)
    return goldenRows(golden);
  json doc = {{"format", kGoldenFormat}, {"description", golden.description}};
  doc.update(streamBody(golden.stream));
  doc["expected"] = {{"depth", rows(golden.depth, golden.stream.width, golden.stream.height)},
                     {"stencil", rows(golden.stencil, golden.stream.width, golden.stream.height)}};
  return doc.dump(1);
}

GoldenVector goldenFromJson(std::string_view text, std::string_view source) {
  return asFormatError([&] { return readGoldenDocument(parseDocument(text, source), source); });
}

namespace {

std::string readFileText(const std::filesystem::path& path) {
  try {
    return recode::io::readBoundedFile(path, recode::io::kMaxJsonFileBytes,
                                       "golden vector or command stream");
  } catch (const recode::io::FileReadError& e) {
    throw FormatError(e.file(), "", e.problem());
  }
}

}  // namespace

GoldenVector readGolden(const std::filesystem::path& path) {
  return goldenFromJson(readFileText(path), path.string());
}

CommandFile readCommandFile(const std::filesystem::path& path) {
  const std::string text = readFileText(path);
  const std::string source = path.string();
  const std::string format = asFormatError([&] {
    const json doc = parseDocument(text, source);
    return Reader(source).string(Reader(source).member(doc, "", "format"), "format");
  });
  if (format == kGoldenFormat)
    return {goldenFromJson(text, source), true};
  if (format == kStreamFormat)
    return {{{}, commandStreamFromJson(text, source), {}, {}}, false};
  throw FormatError(source, "format",
                    "expected \"" + std::string(kGoldenFormat) + "\" or \"" +
                        std::string(kStreamFormat) + "\", got \"" + format + "\"");
}

void writeGolden(const std::filesystem::path& path, const GoldenVector& golden,
                 GoldenLayout layout) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw FormatError(path.string(), "", "cannot open file for writing");
  out << goldenToJson(golden, layout) << '\n';
  if (!out)
    throw FormatError(path.string(), "", "write failed");
}

}  // namespace recode::raster
