#include "recode/raster/golden.hpp"

#include "recode/raster/fixed_point.hpp"

#include <fstream>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>

#include "recode/json/document.hpp"

namespace recode::raster {

namespace {

using nlohmann::json;
using recode::json::childPath;
using recode::json::JsonFieldReader;

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

// Walks a parsed document, remembering the JSON path of every value it reads so that each
// error names where it is. The problems are worded here; the layer words the paths.
class Reader {
 public:
  explicit Reader(std::string_view source) : fields_(std::string(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    fields_.fail(path, problem);
  }

  const json& member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.contains(key))
      fail(path, std::string("missing key \"") + key + "\"");
    return obj.at(key);
  }

  void onlyKeys(const json& obj, const std::string& path,
                std::initializer_list<std::string_view> allowed) const {
    if (!obj.is_object())
      fail(path, "expected an object");
    for (const auto& [key, value] : obj.items()) {
      bool known = false;
      for (std::string_view a : allowed)
        known = known || a == key;
      if (!known)
        fail(childPath(path, key), "unknown key");
    }
  }

  std::int64_t integer(const json& v, const std::string& path, std::int64_t lo,
                       std::int64_t hi) const {
    if (!v.is_number_integer())
      fail(path, "expected an integer");
    const std::int64_t x = v.get<std::int64_t>();
    if (x < lo || x > hi) {
      fail(path, "value " + std::to_string(x) + " outside [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
    }
    return x;
  }

  double number(const json& v, const std::string& path) const {
    if (!v.is_number())
      fail(path, "expected a number");
    return v.get<double>();
  }

  std::string string(const json& v, const std::string& path) const {
    if (!v.is_string())
      fail(path, "expected a string");
    return v.get<std::string>();
  }

  template <class Enum>
  Enum name(const json& v, const std::string& path, std::optional<Enum> (*parse)(std::string_view),
            const char* what) const {
    const std::string s = string(v, path);
    const auto parsed = parse(s);
    if (!parsed)
      fail(path, std::string("unknown ") + what + " \"" + s + "\"");
    return *parsed;
  }

  std::uint8_t byte(const json& v, const std::string& path) const {
    return static_cast<std::uint8_t>(integer(v, path, 0, 255));
  }

  Command command(const json& c, const std::string& path) const {
    if (!c.is_object())
      fail(path, "expected an object");
    const std::string op = string(member(c, path, "op"), childPath(path, "op"));
    const auto field = [&](const char* key) -> const json& { return member(c, path, key); };
    const auto at = [&](const char* key) { return childPath(path, key); };
    if (op == "scissor") {
      onlyKeys(c, path, {"op", "rect"});
      const json& r = field("rect");
      if (!r.is_array() || r.size() != 4)
        fail(at("rect"), "expected [x0, y0, x1, y1]");
      PixelRect rect;
      int* dst[4] = {&rect.x0, &rect.y0, &rect.x1, &rect.y1};
      for (std::size_t i = 0; i < 4; ++i) {
        *dst[i] = static_cast<int>(integer(r[i], childPath(at("rect"), i),
                                           std::numeric_limits<int>::min(),
                                           std::numeric_limits<int>::max()));
      }
      return cmd::Scissor{rect};
    }
    if (op == "clear_depth") {
      onlyKeys(c, path, {"op", "value"});
      const double v = number(field("value"), at("value"));
      if (!(v >= 0.0 && v <= 1.0))
        fail(at("value"), "depth outside [0, 1]");
      return cmd::ClearDepth{v};
    }
    if (op == "clear_stencil") {
      onlyKeys(c, path, {"op", "value"});
      return cmd::ClearStencil{byte(field("value"), at("value"))};
    }
    if (op == "depth_func") {
      onlyKeys(c, path, {"op", "func"});
      return cmd::DepthFunc{name(field("func"), at("func"), parseCompareFunc, "compare function")};
    }
    if (op == "depth_write_mask") {
      onlyKeys(c, path, {"op", "write"});
      if (!field("write").is_boolean())
        fail(at("write"), "expected true or false");
      return cmd::DepthWriteMask{field("write").get<bool>()};
    }
    if (op == "stencil_func") {
      onlyKeys(c, path, {"op", "func", "ref", "value_mask"});
      return cmd::StencilFunc{name(field("func"), at("func"), parseCompareFunc, "compare function"),
                              byte(field("ref"), at("ref")),
                              byte(field("value_mask"), at("value_mask"))};
    }
    if (op == "stencil_ops") {
      onlyKeys(c, path, {"op", "face", "sfail", "dpfail", "dppass"});
      StencilOps ops{name(field("sfail"), at("sfail"), parseStencilOp, "stencil op"),
                     name(field("dpfail"), at("dpfail"), parseStencilOp, "stencil op"),
                     name(field("dppass"), at("dppass"), parseStencilOp, "stencil op")};
      return cmd::StencilOpsCmd{name(field("face"), at("face"), parseFace, "face"), ops};
    }
    if (op == "stencil_write_mask") {
      onlyKeys(c, path, {"op", "mask"});
      return cmd::StencilWriteMask{byte(field("mask"), at("mask"))};
    }
    if (op == "cull") {
      onlyKeys(c, path, {"op", "mode"});
      return cmd::Cull{name(field("mode"), at("mode"), parseCullMode, "cull mode")};
    }
    if (op == "draw") {
      onlyKeys(c, path, {"op", "vertices_fixed", "indices"});
      return draw(c, path);
    }
    fail(childPath(path, "op"), "unknown command \"" + op + "\"");
  }

  cmd::Draw draw(const json& c, const std::string& path) const {
    cmd::Draw d;
    const json& vs = member(c, path, "vertices_fixed");
    const std::string vpath = childPath(path, "vertices_fixed");
    if (!vs.is_array())
      fail(vpath, "expected an array of [x_fixed, y_fixed, z]");
    const std::int64_t limit = static_cast<std::int64_t>(kMaxWindowCoordinate) * kSubpixelOne;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      const std::string p = childPath(vpath, i);
      if (!vs[i].is_array() || vs[i].size() != 3)
        fail(p, "expected [x_fixed, y_fixed, z]");
      WindowVertex v;
      v.x = static_cast<float>(integer(vs[i][0], childPath(p, 0), -limit, limit)) / kSubpixelOne;
      v.y = static_cast<float>(integer(vs[i][1], childPath(p, 1), -limit, limit)) / kSubpixelOne;
      const double z = number(vs[i][2], childPath(p, 2));
      if (!(z >= 0.0 && z <= 1.0))
        fail(childPath(p, 2), "depth outside [0, 1]");
      v.z = static_cast<float>(z);
      if (static_cast<double>(v.z) != z)
        fail(childPath(p, 2), "depth is not a single-precision float");
      d.vertices.push_back(v);
    }
    const json& is = member(c, path, "indices");
    const std::string ipath = childPath(path, "indices");
    if (!is.is_array())
      fail(ipath, "expected an array of vertex indices");
    if (is.size() % 3 != 0)
      fail(ipath, "index count " + std::to_string(is.size()) + " is not a multiple of 3");
    for (std::size_t i = 0; i < is.size(); ++i) {
      d.indices.push_back(static_cast<std::uint32_t>(integer(
          is[i], childPath(ipath, i), 0, static_cast<std::int64_t>(d.vertices.size()) - 1)));
    }
    return d;
  }

  CommandStream stream(const json& doc) const {
    CommandStream s;
    s.width = static_cast<int>(integer(member(doc, "", "width"), "width", 1, kMaxFramebufferSize));
    s.height =
        static_cast<int>(integer(member(doc, "", "height"), "height", 1, kMaxFramebufferSize));
    const json& commands = member(doc, "", "commands");
    if (!commands.is_array())
      fail("commands", "expected an array");
    for (std::size_t i = 0; i < commands.size(); ++i) {
      s.commands.push_back(command(commands[i], childPath("commands", i)));
    }
    return s;
  }

  template <class T>
  std::vector<T> buffer(const json& v, const std::string& path, int width, int height,
                        std::int64_t maxValue) const {
    if (!v.is_array() || v.size() != static_cast<std::size_t>(height)) {
      fail(path, "expected " + std::to_string(height) + " rows");
    }
    std::vector<T> out;
    out.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < v.size(); ++y) {
      const std::string rp = childPath(path, y);
      if (!v[y].is_array() || v[y].size() != static_cast<std::size_t>(width)) {
        fail(rp, "expected a row of " + std::to_string(width) + " values");
      }
      for (std::size_t x = 0; x < v[y].size(); ++x) {
        out.push_back(static_cast<T>(integer(v[y][x], childPath(rp, x), 0, maxValue)));
      }
    }
    return out;
  }

  void format(const json& doc, std::string_view expected) const {
    const std::string f = string(member(doc, "", "format"), "format");
    if (f != expected)
      fail("format", "expected \"" + std::string(expected) + "\", got \"" + f + "\"");
  }

 private:
  JsonFieldReader fields_;
};

// Through the layer: malformed JSON and repeated keys are refused there, with line:column
// or the JSON path.
json parseDocument(std::string_view text, std::string_view source) {
  json doc = recode::json::parseJsonDocument(text, std::string(source));
  if (!doc.is_object())
    Reader(source).fail("", "expected an object");
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

std::string goldenToJson(const GoldenVector& golden) {
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
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw FormatError(path.string(), "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
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

void writeGolden(const std::filesystem::path& path, const GoldenVector& golden) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw FormatError(path.string(), "", "cannot open file for writing");
  out << goldenToJson(golden) << '\n';
  if (!out)
    throw FormatError(path.string(), "", "write failed");
}

}  // namespace recode::raster
