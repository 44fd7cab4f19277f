// Tessellation to a triangle budget, tidy numbers and a portable random source for the
// built-in scenes.
#include "scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "recode/geometry/generators.hpp"

namespace recode::core::detail {

namespace {

int atLeast(double x, int lo) {
  return std::max(lo, static_cast<int>(std::lround(x)));
}

struct Split {
  int segments;
  int bands;
};

// Segments s >= 3 and bands b >= 1 with perBand * b * s as near `triangles` as possible;
// among equally near splits, b nearest `idealBands` (round shapes look round when b is
// about s / 2 for an ellipsoid, s / 4 for a capped cone).
Split splitTriangles(int triangles, int perBand, double idealBands) {
  Split best{3, 1};
  long long bestError = -1;
  double bestShape = 0.0;
  for (int b = 1; b <= std::max(1, triangles / (perBand * 3)); ++b) {
    const int s = atLeast(static_cast<double>(triangles) / (perBand * b), 3);
    const long long error = std::llabs(static_cast<long long>(perBand) * b * s - triangles);
    const double shape = std::abs(b - idealBands);
    if (bestError < 0 || error < bestError || (error == bestError && shape < bestShape)) {
      best = {s, b};
      bestError = error;
      bestShape = shape;
    }
  }
  return best;
}

}  // namespace

// Cone: F = 2 s.
Block coneBlock(double radius, double height, int triangles) {
  const int s = atLeast(triangles / 2.0, 3);
  Json shape;
  shape["type"] = "cone";
  shape["radius"] = tidy(radius);
  shape["height"] = tidy(height);
  shape["segments"] = s;
  return {shape, makeCone(tidy(radius), tidy(height), s)};
}

// Cylinder: F = 4 s.
Block cylinderBlock(double radius, double height, int triangles) {
  const int s = atLeast(triangles / 4.0, 3);
  Json shape;
  shape["type"] = "cylinder";
  shape["radius"] = tidy(radius);
  shape["height"] = tidy(height);
  shape["segments"] = s;
  return {shape, makeCylinder(tidy(radius), tidy(height), s)};
}

// Ellipsoid: F = 2 (rings - 1) s, about as many rings as half the segments.
Block ellipsoidBlock(double a, double b, double c, int triangles) {
  const Split split = splitTriangles(triangles, 2, std::sqrt(triangles) / 2.0);
  const int s = split.segments, bands = split.bands;  // bands = rings - 1
  Json shape;
  shape["type"] = "ellipsoid";
  shape["radii"] = vec(a, b, c);
  shape["segments"] = s;
  shape["rings"] = bands + 1;
  return {shape, makeEllipsoid(tidy(a), tidy(b), tidy(c), s, bands + 1)};
}

Block sphereBlock(double radius, int triangles) {
  Block e = ellipsoidBlock(radius, radius, radius, triangles);
  Json shape;
  shape["type"] = "sphere";
  shape["radius"] = tidy(radius);
  shape["segments"] = e.shape["segments"];
  shape["rings"] = e.shape["rings"];
  return {shape,
          makeSphere(tidy(radius), e.shape["segments"].get<int>(), e.shape["rings"].get<int>())};
}

// Capped cone: F = 4 rings s, about a quarter as many rings as segments.
Block cappedConeBlock(double r0, double r1, double height, int triangles) {
  const Split split = splitTriangles(triangles, 4, std::sqrt(triangles) / 4.0);
  const int s = split.segments, rings = split.bands;
  Json shape;
  shape["type"] = "capped_cone";
  shape["radius0"] = tidy(r0);
  shape["radius1"] = tidy(r1);
  shape["height"] = tidy(height);
  shape["segments"] = s;
  shape["rings"] = rings;
  return {shape, makeCappedCone(tidy(r0), tidy(r1), tidy(height), s, rings)};
}

double tidy(double x, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double r = std::round(x * scale) / scale;
  return r == 0.0 ? 0.0 : r;  // no "-0.0" in the files
}

Json vec(double x, double y, double z, int decimals) {
  return Json::array({tidy(x, decimals), tidy(y, decimals), tidy(z, decimals)});
}

std::uint64_t SceneRandom::next() {
  state_ += 0x9E3779B97F4A7C15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double SceneRandom::uniform(double lo, double hi) {
  const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;
  return tidy(lo + (hi - lo) * unit, 4);
}

namespace {

// Arrays of numbers (and arrays of such arrays, like a box's two corners) go on one line;
// objects and other arrays are indented two spaces per level.
bool isFlat(const Json& value) {
  if (!value.is_array())
    return value.is_primitive();
  for (const Json& element : value)
    if (!(element.is_primitive() || (element.is_array() && isFlat(element))))
      return false;
  return true;
}

void write(std::string& out, const Json& value, int indent) {
  if (value.is_array() && isFlat(value)) {
    out += '[';
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i > 0)
        out += ", ";
      write(out, value[i], indent);
    }
    out += ']';
    return;
  }
  if (!value.is_structured()) {
    out += value.dump();
    return;
  }
  const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
  const bool object = value.is_object();
  if (value.empty()) {
    out += object ? "{}" : "[]";
    return;
  }
  out += object ? "{\n" : "[\n";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!first)
      out += ",\n";
    first = false;
    out += inner;
    if (object)
      out += Json(it.key()).dump() + ": ";
    write(out, it.value(), indent + 2);
  }
  out += '\n' + std::string(static_cast<std::size_t>(indent), ' ') + (object ? '}' : ']');
}

}  // namespace

std::string sceneText(const Json& scene) {
  std::string out;
  write(out, scene, 0);
  return out + "\n";
}

}  // namespace recode::core::detail
