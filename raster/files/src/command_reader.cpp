// The commands of a command stream, one JSON object each (docs/rasterization.md, section 8).
#include <limits>

#include "document_reader.hpp"
#include "recode/raster/fixed_point.hpp"

namespace recode::raster::files {

namespace {

// One command's fields, each read with the path that names it in errors.
class CommandFields {
 public:
  CommandFields(const Reader& r, const json& c, const std::string& path)
      : r_(r), c_(c), path_(path) {}

  const json& field(const char* key) const { return r_.member(c_, path_, key); }
  std::string at(const char* key) const { return childPath(path_, key); }

  std::uint8_t byte(const char* key) const { return r_.byte(field(key), at(key)); }

  template <class Enum>
  Enum name(const char* key, std::optional<Enum> (*parse)(std::string_view),
            const char* what) const {
    return r_.name(field(key), at(key), parse, what);
  }

  PixelRect rect(const char* key) const {
    const json& r = field(key);
    if (!r.is_array() || r.size() != 4)
      r_.fail(at(key), "expected [x0, y0, x1, y1]");
    PixelRect rect;
    int* dst[4] = {&rect.x0, &rect.y0, &rect.x1, &rect.y1};
    for (std::size_t i = 0; i < 4; ++i) {
      *dst[i] =
          static_cast<int>(r_.integer(r[i], childPath(at(key), i), std::numeric_limits<int>::min(),
                                      std::numeric_limits<int>::max()));
    }
    return rect;
  }

  double depth(const char* key) const {
    const double v = r_.number(field(key), at(key));
    if (!(v >= 0.0 && v <= 1.0))
      r_.fail(at(key), "depth outside [0, 1]");
    return v;
  }

  bool boolean(const char* key) const {
    if (!field(key).is_boolean())
      r_.fail(at(key), "expected true or false");
    return field(key).get<bool>();
  }

 private:
  const Reader& r_;
  const json& c_;
  const std::string& path_;
};

}  // namespace

// Each command's keys are checked before any of its values, so an unknown key is reported
// ahead of a wrong value.
Command Reader::command(const json& c, const std::string& path) const {
  requireObject(c, path);
  const std::string op = string(member(c, path, "op"), childPath(path, "op"));
  const CommandFields f(*this, c, path);
  if (op == "scissor") {
    onlyKeys(c, path, {"op", "rect"});
    return cmd::Scissor{f.rect("rect")};
  }
  if (op == "clear_depth") {
    onlyKeys(c, path, {"op", "value"});
    return cmd::ClearDepth{f.depth("value")};
  }
  if (op == "clear_stencil") {
    onlyKeys(c, path, {"op", "value"});
    return cmd::ClearStencil{f.byte("value")};
  }
  if (op == "depth_func") {
    onlyKeys(c, path, {"op", "func"});
    return cmd::DepthFunc{f.name("func", parseCompareFunc, "compare function")};
  }
  if (op == "depth_write_mask") {
    onlyKeys(c, path, {"op", "write"});
    return cmd::DepthWriteMask{f.boolean("write")};
  }
  if (op == "stencil_func") {
    onlyKeys(c, path, {"op", "func", "ref", "value_mask"});
    return cmd::StencilFunc{f.name("func", parseCompareFunc, "compare function"), f.byte("ref"),
                            f.byte("value_mask")};
  }
  if (op == "stencil_ops") {
    onlyKeys(c, path, {"op", "face", "sfail", "dpfail", "dppass"});
    // The ops are read before the face: a command wrong in both still reports the op.
    StencilOps ops{f.name("sfail", parseStencilOp, "stencil op"),
                   f.name("dpfail", parseStencilOp, "stencil op"),
                   f.name("dppass", parseStencilOp, "stencil op")};
    return cmd::StencilOpsCmd{f.name("face", parseFace, "face"), ops};
  }
  if (op == "stencil_write_mask") {
    onlyKeys(c, path, {"op", "mask"});
    return cmd::StencilWriteMask{f.byte("mask")};
  }
  if (op == "cull") {
    onlyKeys(c, path, {"op", "mode"});
    return cmd::Cull{f.name("mode", parseCullMode, "cull mode")};
  }
  if (op == "draw") {
    onlyKeys(c, path, {"op", "vertices_fixed", "indices"});
    return draw(c, path);
  }
  fail(childPath(path, "op"), "unknown command \"" + op + "\"");
}

cmd::Draw Reader::draw(const json& c, const std::string& path) const {
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
    d.indices.push_back(static_cast<std::uint32_t>(
        integer(is[i], childPath(ipath, i), 0, static_cast<std::int64_t>(d.vertices.size()) - 1)));
  }
  return d;
}

CommandStream Reader::stream(const json& doc) const {
  CommandStream s;
  s.width = static_cast<int>(integer(member(doc, "", "width"), "width", 1, kMaxFramebufferSize));
  s.height = static_cast<int>(integer(member(doc, "", "height"), "height", 1, kMaxFramebufferSize));
  const json& commands = member(doc, "", "commands");
  if (!commands.is_array())
    fail("commands", "expected an array");
  for (std::size_t i = 0; i < commands.size(); ++i) {
    s.commands.push_back(command(commands[i], childPath("commands", i)));
  }
  return s;
}

}  // namespace recode::raster::files
