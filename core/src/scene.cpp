#include "recode/core/scene.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "recode/core/generators.hpp"
#include "recode/core/mesh_error.hpp"
#include "recode/core/mesh_io.hpp"
#include "recode/core/validate.hpp"

namespace recode::core {

SceneError::SceneError(const std::string& file, const std::string& jsonPath,
                       const std::string& problem)
    : std::runtime_error(file + ": " + (jsonPath.empty() ? "" : jsonPath + ": ") + problem),
      file_(file),
      jsonPath_(jsonPath) {}

SceneError::SceneError(const std::string& file, int line, int column, const std::string& problem)
    : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                         problem),
      file_(file),
      line_(line),
      column_(column) {}

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// sin and cos of an angle in degrees; exact (0, +-1) for whole multiples of 90 degrees.
std::pair<double, double> sinCosDegrees(double degrees) {
  const double reduced = std::fmod(degrees, 360.0);  // exact; in (-360, 360), sign of degrees
  if (std::fmod(reduced, 90.0) == 0.0) {
    const int quarter = (static_cast<int>(reduced / 90.0) % 4 + 4) % 4;
    static constexpr std::pair<double, double> kQuarterTurns[4] = {
        {0.0, 1.0}, {1.0, 0.0}, {0.0, -1.0}, {-1.0, 0.0}};
    return kQuarterTurns[quarter];
  }
  const double radians = reduced * (std::numbers::pi / 180.0);
  return {std::sin(radians), std::cos(radians)};
}

// ---- JSON text -> document ------------------------------------------------------------

// Display form of a JSON path: "(root)" for the top level.
std::string displayPath(const std::string& path) {
  return path.empty() ? "(root)" : path;
}

// A value as JSON text, for messages (invalid UTF-8, which the parser does not let through
// anyway, would be replaced rather than throw).
std::string asText(const json& v) {
  return v.dump(-1, ' ', false, json::error_handler_t::replace);
}

// path.key, or path["key"] (JSON-escaped) when the key is not a plain identifier.
std::string childPath(const std::string& path, const std::string& key) {
  const bool identifier = !key.empty() && !(key[0] >= '0' && key[0] <= '9') &&
                          std::all_of(key.begin(), key.end(), [](char c) {
                            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                                   (c >= '0' && c <= '9') || c == '_';
                          });
  if (!identifier)
    return path + "[" + asText(json(key)) + "]";
  return path.empty() ? key : path + "." + key;
}

std::string childPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// Builds the document from nlohmann's SAX events, so that (unlike json::parse) a repeated
// key is an error instead of silently keeping the last value, and the byte position of a
// syntax error or a number that overflows a double is known.
class DocumentBuilder : public nlohmann::json_sax<json> {
 public:
  bool null() override { return add(json(nullptr)); }
  bool boolean(bool value) override { return add(json(value)); }
  bool number_integer(number_integer_t value) override { return add(json(value)); }
  bool number_unsigned(number_unsigned_t value) override { return add(json(value)); }
  bool number_float(number_float_t value, const string_t& /*text*/) override {
    return add(json(value));
  }
  bool string(string_t& value) override { return add(json(std::move(value))); }
  bool binary(binary_t& value) override { return add(json::binary(std::move(value))); }
  bool start_object(std::size_t /*elements*/) override { return open(json::object()); }
  bool end_object() override {
    open_.pop_back();
    return true;
  }
  bool start_array(std::size_t /*elements*/) override { return open(json::array()); }
  bool end_array() override {
    open_.pop_back();
    return true;
  }
  bool key(string_t& name) override {
    const Container& parent = open_.back();
    if (parent.value->contains(name)) {
      duplicatePath_ = childPath(parent.path, name);
      return false;
    }
    key_ = name;
    return true;
  }
  bool parse_error(std::size_t position, const std::string& lastToken,
                   const nlohmann::detail::exception& error) override {
    errorPosition_ = position;
    errorToken_ = lastToken;
    errorMessage_ = error.what();
    return false;
  }

  [[nodiscard]] json& document() { return root_; }
  [[nodiscard]] const std::optional<std::string>& duplicatePath() const { return duplicatePath_; }
  [[nodiscard]] std::size_t errorPosition() const { return errorPosition_; }
  [[nodiscard]] const std::string& errorToken() const { return errorToken_; }
  [[nodiscard]] const std::string& errorMessage() const { return errorMessage_; }

 private:
  struct Container {
    json* value;
    std::string path;
  };

  // Places a value in the innermost open container (or as the document) and returns it.
  json* place(json value, std::string* path) {
    if (open_.empty()) {
      root_ = std::move(value);
      *path = "";
      return &root_;
    }
    Container& parent = open_.back();
    if (parent.value->is_array()) {
      *path = childPath(parent.path, parent.value->size());
      parent.value->push_back(std::move(value));
      return &parent.value->back();
    }
    *path = childPath(parent.path, key_);
    json& slot = (*parent.value)[key_];
    slot = std::move(value);
    return &slot;
  }
  bool add(json value) {
    std::string path;
    place(std::move(value), &path);
    return true;
  }
  bool open(json container) {
    std::string path;
    json* placed = place(std::move(container), &path);
    open_.push_back({placed, std::move(path)});
    return true;
  }

  json root_;
  std::vector<Container> open_;
  std::string key_;
  std::optional<std::string> duplicatePath_;
  std::size_t errorPosition_ = 0;
  std::string errorToken_;
  std::string errorMessage_;
};

// nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: syntax
// error ..." without the exception id and its own position (ours is printed instead).
std::string plainParseMessage(std::string message) {
  if (!message.empty() && message.front() == '[') {
    const std::size_t close = message.find("] ");
    if (close != std::string::npos)
      message.erase(0, close + 2);
  }
  const std::string prefix = "parse error";
  if (message.starts_with(prefix)) {
    const std::size_t colon = message.find(": ");
    if (colon != std::string::npos)
      message.erase(0, colon + 2);
  }
  return message;
}

// nlohmann's "last token" is only the token itself for strings and numbers (for other
// tokens it may still hold the text since the last string or number): true for a string
// token ('"', anything without an unescaped '"', then at most a closing '"') or a number.
bool isStringOrNumberToken(const std::string& token) {
  if (token.empty())
    return false;
  if (token.front() == '"') {
    for (std::size_t i = 1; i < token.size(); ++i) {
      if (token[i] == '\\')
        ++i;
      else if (token[i] == '"')
        return i + 1 == token.size();
    }
    return true;
  }
  return (token.front() == '-' || (token.front() >= '0' && token.front() <= '9')) &&
         token.find_first_not_of("0123456789+-.eE") == std::string::npos;
}

json parseDocument(std::string_view text, const std::string& sourceName) {
  DocumentBuilder builder;
  const bool ok = json::sax_parse(text.begin(), text.end(), &builder);
  if (ok)
    return std::move(builder.document());
  if (builder.duplicatePath())
    throw SceneError(sourceName, *builder.duplicatePath(), "duplicate key");
  // nlohmann's position counts the characters read, up to the last one it looked at (one
  // more when it read the end of input). Point there, or at the first character of the
  // offending string or number when nlohmann reports one that ends at that position.
  const std::size_t end = std::min(builder.errorPosition(), text.size() + 1);
  std::size_t offending = end > 0 ? end - 1 : 0;
  const std::string& token = builder.errorToken();
  if (isStringOrNumberToken(token) && token.size() <= end && end <= text.size() &&
      text.substr(end - token.size(), token.size()) == token) {
    offending = end - token.size();
  }
  offending = std::min(offending, text.size());
  const std::string_view before = text.substr(0, offending);
  const std::size_t lastNewline = before.rfind('\n');
  const std::size_t lineStart = lastNewline == std::string_view::npos ? 0 : lastNewline + 1;
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t column = offending - lineStart + 1;
  throw SceneError(sourceName, static_cast<int>(std::min<std::ptrdiff_t>(line, INT_MAX)),
                   static_cast<int>(std::min<std::size_t>(column, INT_MAX)),
                   "invalid JSON: " + plainParseMessage(builder.errorMessage()));
}

// ---- document -> scene ----------------------------------------------------------------

// What a value is, for "expected ..., got <what>".
std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return asText(v);
    default:
      return "a binary value";
  }
}

struct ShapeSpec {
  std::string_view type;
  std::initializer_list<std::string_view> keys;  // besides "type"
};

constexpr std::string_view kShapeTypesText = "cone, cylinder, capped_cone, ellipsoid, sphere, box";

// Walks the document; every error names the JSON path of the value it is about.
class SceneReader {
 public:
  SceneReader(const std::string& sourceName, const fs::path& baseDir)
      : source_(sourceName), baseDir_(baseDir) {}

  Scene scene(const json& doc) const {
    Scene scene;
    scene.sourceName = source_;
    expectObject(doc, "");
    onlyKeys(doc, "", {"view", "objects", "frames"});
    if (doc.contains("view"))
      scene.view = view(doc.at("view"), "view");
    if (doc.contains("frames"))
      scene.frames = static_cast<int>(integer(doc.at("frames"), "frames", 1, INT_MAX));
    if (!doc.contains("objects"))
      fail("", "missing key \"objects\" (the list of objects)");
    const json& objects = doc.at("objects");
    if (!objects.is_array())
      fail("objects", "expected an array of objects, got " + describe(objects));
    if (objects.empty())
      fail("objects", "expected at least one object, got an empty array");
    for (std::size_t i = 0; i < objects.size(); ++i)
      scene.objects.push_back(object(objects[i], i));
    return scene;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw SceneError(source_, displayPath(path), problem);
  }

  void expectObject(const json& v, const std::string& path) const {
    if (!v.is_object())
      fail(path, "expected an object, got " + describe(v));
  }

  void onlyKeys(const json& obj, const std::string& path,
                std::initializer_list<std::string_view> allowed,
                const std::string& context = "") const {
    for (const auto& [key, value] : obj.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end())
        continue;
      std::string list;
      for (std::string_view a : allowed)
        list += (list.empty() ? "" : ", ") + std::string(a);
      fail(childPath(path, key), "unknown key" + context + " (allowed: " + list + ")");
    }
  }

  double number(const json& v, const std::string& path) const {
    if (!v.is_number())
      fail(path, "expected a number, got " + describe(v));
    const double x = v.get<double>();
    if (!std::isfinite(x))
      fail(path, "expected a finite number, got " + asText(v));
    return x;
  }

  double positive(const json& v, const std::string& path) const {
    if (!v.is_number())
      fail(path, "expected a positive number, got " + describe(v));
    const double x = number(v, path);
    if (!(x > 0.0))
      fail(path, "expected a positive number, got " + asText(v));
    return x;
  }

  std::int64_t integer(const json& v, const std::string& path, std::int64_t lo,
                       std::int64_t hi) const {
    const std::string range = "an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
    if (!v.is_number_integer())
      fail(path, "expected " + range + ", got " + describe(v));
    if (v.is_number_unsigned()) {
      const std::uint64_t u = v.get<std::uint64_t>();
      if ((lo > 0 && u < static_cast<std::uint64_t>(lo)) || u > static_cast<std::uint64_t>(hi))
        fail(path, "expected " + range + ", got " + asText(v));
      return static_cast<std::int64_t>(u);
    }
    const std::int64_t x = v.get<std::int64_t>();
    if (x < lo || x > hi)
      fail(path, "expected " + range + ", got " + asText(v));
    return x;
  }

  std::string nonEmptyString(const json& v, const std::string& path) const {
    if (!v.is_string())
      fail(path, "expected a string, got " + describe(v));
    std::string s = v.get<std::string>();
    if (s.empty())
      fail(path, "expected a non-empty string, got \"\"");
    return s;
  }

  // An array of exactly n elements.
  const json& array(const json& v, const std::string& path, std::size_t n, const char* what) const {
    if (!v.is_array())
      fail(path, std::string("expected an array of ") + what + ", got " + describe(v));
    if (v.size() != n) {
      fail(path, std::string("expected an array of ") + what + ", got " + std::to_string(v.size()) +
                     " element" + (v.size() == 1 ? "" : "s"));
    }
    return v;
  }

  Eigen::Vector3d vector3(const json& v, const std::string& path) const {
    array(v, path, 3, "3 numbers [x, y, z]");
    return {number(v[0], childPath(path, 0)), number(v[1], childPath(path, 1)),
            number(v[2], childPath(path, 2))};
  }

  ViewSpec view(const json& v, const std::string& path) const {
    expectObject(v, path);
    onlyKeys(v, path, {"axis", "window", "resolution", "pixel_size"});
    ViewSpec spec;
    if (v.contains("axis")) {
      const std::string p = childPath(path, "axis");
      const json& a = v.at("axis");
      if (!a.is_string())
        fail(p, "expected \"x\", \"y\" or \"z\", got " + describe(a));
      const std::string s = a.get<std::string>();
      if (s == "x")
        spec.axis = ViewAxis::X;
      else if (s == "y")
        spec.axis = ViewAxis::Y;
      else if (s == "z")
        spec.axis = ViewAxis::Z;
      else
        fail(p, "expected \"x\", \"y\" or \"z\", got " + asText(a));
    }
    if (v.contains("window")) {
      const std::string p = childPath(path, "window");
      const json& w = array(v.at("window"), p, 4, "4 numbers [umin, vmin, umax, vmax]");
      ViewWindow window;
      window.umin = number(w[0], childPath(p, 0));
      window.vmin = number(w[1], childPath(p, 1));
      window.umax = number(w[2], childPath(p, 2));
      window.vmax = number(w[3], childPath(p, 3));
      if (!(window.umin < window.umax)) {
        fail(p, "umin (" + asText(w[0]) + ") must be less than umax (" + asText(w[2]) + ")");
      }
      if (!(window.vmin < window.vmax)) {
        fail(p, "vmin (" + asText(w[1]) + ") must be less than vmax (" + asText(w[3]) + ")");
      }
      if (!std::isfinite(window.umax - window.umin) || !std::isfinite(window.vmax - window.vmin))
        fail(p, "the window's width or height overflows a double");
      spec.window = window;
    }
    if (v.contains("resolution")) {
      const std::string p = childPath(path, "resolution");
      const json& r = array(v.at("resolution"), p, 2, "2 integers [W, H]");
      spec.resolution =
          std::array<int, 2>{static_cast<int>(integer(r[0], childPath(p, 0), 1, 16384)),
                             static_cast<int>(integer(r[1], childPath(p, 1), 1, 16384))};
    }
    if (v.contains("pixel_size")) {
      const std::string p = childPath(path, "pixel_size");
      if (spec.resolution)
        fail(p, "cannot be given together with \"resolution\" (give one of the two)");
      spec.pixelSize = positive(v.at("pixel_size"), p);
    }
    return spec;
  }

  SceneObject object(const json& v, std::size_t index) const {
    const std::string path = childPath("objects", index);
    expectObject(v, path);
    onlyKeys(v, path, {"name", "mesh", "shape", "children", "position", "rotation_deg", "motion"});
    if (v.contains("children")) {
      fail(childPath(path, "children"),
           "hierarchical objects (\"children\") are not supported yet; give a \"mesh\" or a "
           "\"shape\"");
    }
    SceneObject object;
    object.jsonPath = path;
    object.name = v.contains("name") ? nonEmptyString(v.at("name"), childPath(path, "name"))
                                     : "object " + std::to_string(index);
    if (v.contains("position"))
      object.position = vector3(v.at("position"), childPath(path, "position"));
    if (v.contains("rotation_deg"))
      object.rotationDeg = vector3(v.at("rotation_deg"), childPath(path, "rotation_deg"));
    if (v.contains("motion"))
      object.motion = motion(v.at("motion"), childPath(path, "motion"));

    const bool hasMesh = v.contains("mesh");
    const bool hasShape = v.contains("shape");
    if (hasMesh && hasShape)
      fail(path, "give exactly one of \"mesh\" and \"shape\", not both");
    if (!hasMesh && !hasShape)
      fail(path, "missing \"mesh\" or \"shape\" (give exactly one)");
    if (hasMesh) {
      const std::string p = childPath(path, "mesh");
      const fs::path file = baseDir_ / fs::path(nonEmptyString(v.at("mesh"), p));
      try {
        object.localMesh = readMesh(file);
        validateConvexBlock(object.localMesh, file.string());
      } catch (const MeshError& e) {
        fail(p, e.what());
      }
    } else {
      const std::string p = childPath(path, "shape");
      std::string type;
      object.localMesh = shape(v.at("shape"), p, &type);
      try {
        validateConvexBlock(object.localMesh, "the generated " + type);
      } catch (const MeshError& e) {
        fail(p, e.what());
      }
    }
    return object;
  }

  Motion motion(const json& v, const std::string& path) const {
    expectObject(v, path);
    onlyKeys(v, path, {"velocity", "angular_velocity_deg"});
    Motion m;
    if (v.contains("velocity"))
      m.velocity = vector3(v.at("velocity"), childPath(path, "velocity"));
    if (v.contains("angular_velocity_deg")) {
      m.angularVelocityDeg =
          vector3(v.at("angular_velocity_deg"), childPath(path, "angular_velocity_deg"));
    }
    return m;
  }

  // The shape's mesh; *typeName is set to its "type".
  TriangleMesh shape(const json& v, const std::string& path, std::string* typeName) const {
    static const ShapeSpec kShapes[] = {
        {"cone", {"radius", "height", "segments"}},
        {"cylinder", {"radius", "height", "segments"}},
        {"capped_cone", {"radius0", "radius1", "height", "segments", "rings"}},
        {"ellipsoid", {"radii", "segments", "rings"}},
        {"sphere", {"radius", "segments", "rings"}},
        {"box", {"size"}},
    };
    expectObject(v, path);
    if (!v.contains("type"))
      fail(path, "missing key \"type\" (one of " + std::string(kShapeTypesText) + ")");
    const std::string typePath = childPath(path, "type");
    const json& t = v.at("type");
    if (!t.is_string()) {
      fail(typePath,
           "expected a shape type (" + std::string(kShapeTypesText) + "), got " + describe(t));
    }
    const std::string type = t.get<std::string>();
    *typeName = type;
    const auto spec = std::find_if(std::begin(kShapes), std::end(kShapes),
                                   [&](const ShapeSpec& s) { return s.type == type; });
    if (spec == std::end(kShapes)) {
      fail(typePath, "unknown shape type " + asText(t) + " (expected one of " +
                         std::string(kShapeTypesText) + ")");
    }
    for (const auto& [key, value] : v.items()) {
      if (key == "type" || std::find(spec->keys.begin(), spec->keys.end(), key) != spec->keys.end())
        continue;
      std::string list = "type";
      for (std::string_view k : spec->keys)
        list += ", " + std::string(k);
      fail(childPath(path, key), "unknown key for a " + type + " shape (allowed: " + list + ")");
    }

    const auto size = [&](const char* key) -> double {
      const std::string p = childPath(path, key);
      if (!v.contains(key))
        fail(path, std::string("missing key \"") + key + "\" for a " + type + " shape");
      return positive(v.at(key), p);
    };
    const auto count = [&](const char* key, int fallback, int lo) -> int {
      if (!v.contains(key))
        return fallback;
      return static_cast<int>(integer(v.at(key), childPath(path, key), lo, INT_MAX));
    };
    const auto sizes3 = [&](const char* key, const char* what) -> Eigen::Vector3d {
      const std::string p = childPath(path, key);
      if (!v.contains(key))
        fail(path, std::string("missing key \"") + key + "\" for a " + type + " shape");
      const json& a = array(v.at(key), p, 3, what);
      return {positive(a[0], childPath(p, 0)), positive(a[1], childPath(p, 1)),
              positive(a[2], childPath(p, 2))};
    };

    try {
      if (type == "cone" || type == "cylinder") {
        const double radius = size("radius");
        const double height = size("height");
        const int segments = count("segments", 32, 3);
        return type == "cone" ? makeCone(radius, height, segments)
                              : makeCylinder(radius, height, segments);
      }
      if (type == "capped_cone") {
        const double r0 = size("radius0");
        const double r1 = size("radius1");
        const double height = size("height");
        const int segments = count("segments", 32, 3);
        const int rings = count("rings", 8, 1);
        if (!(height > std::abs(r0 - r1))) {
          fail(childPath(path, "height"),
               "must exceed |radius0 - radius1| = " + asText(json(std::abs(r0 - r1))) +
                   " (otherwise one sphere contains the other), got " + asText(v.at("height")));
        }
        return makeCappedCone(r0, r1, height, segments, rings);
      }
      if (type == "ellipsoid") {
        const Eigen::Vector3d radii = sizes3("radii", "3 positive numbers [a, b, c]");
        const int segments = count("segments", 32, 3);
        const int rings = count("rings", 16, 2);
        return makeEllipsoid(radii.x(), radii.y(), radii.z(), segments, rings);
      }
      if (type == "sphere") {
        const double radius = size("radius");
        const int segments = count("segments", 32, 3);
        const int rings = count("rings", 16, 2);
        return makeSphere(radius, segments, rings);
      }
      const Eigen::Vector3d full = sizes3("size", "3 positive numbers [sx, sy, sz]");
      return makeBox(full / 2.0);
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
  }

  std::string source_;
  fs::path baseDir_;
};

}  // namespace

Eigen::Isometry3d SceneObject::pose() const {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = rotationFromDegrees(rotationDeg);
  transform.translation() = position;
  return transform;
}

TriangleMesh SceneObject::worldMesh() const {
  return transformed(localMesh, pose());
}

Eigen::Matrix3d rotationFromDegrees(const Eigen::Vector3d& degrees) {
  const auto [sx, cx] = sinCosDegrees(degrees.x());
  const auto [sy, cy] = sinCosDegrees(degrees.y());
  const auto [sz, cz] = sinCosDegrees(degrees.z());
  Eigen::Matrix3d rx;
  rx << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  Eigen::Matrix3d ry;
  ry << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  Eigen::Matrix3d rz;
  rz << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  return rz * ry * rx;
}

Scene parseScene(std::string_view jsonText, const std::string& sourceName,
                 const std::filesystem::path& baseDir) {
  const json doc = parseDocument(jsonText, sourceName);
  return SceneReader(sourceName, baseDir).scene(doc);
}

Scene loadScene(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!fs::exists(file, ec))
    throw SceneError(name, "", "cannot open scene file (file not found)");
  if (fs::is_directory(file, ec))
    throw SceneError(name, "", "cannot open scene file (it is a directory)");
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw SceneError(name, "", "cannot open scene file (not readable)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw SceneError(name, "", "error while reading the scene file");
  return parseScene(text.str(), name, file.parent_path());
}

}  // namespace recode::core
