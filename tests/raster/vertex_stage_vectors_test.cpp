// The conformance kit's vertex-stage vectors (recode/kit/vertex_stage_vectors.hpp): the contract
// (raster::vertexStage) reproduces every expected window vertex bit for bit, every wrong reading
// of docs/rasterization.md section 2.1 gets at least kMinVertexStageCatches vectors wrong (the
// test prints each with the number of vectors and vertices that catch it), the vectors hold the
// special cases they claim, and data/golden/vertex-stage.jsonl is what the generator writes.

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "recode/kit/vertex_stage_vectors.hpp"

using recode::kit::kMinVertexStageCatches;
using recode::kit::VertexStageReading;
using recode::kit::VertexStageReadingInfo;
using recode::kit::VertexStageVector;
using recode::raster::WindowPosition;
using recode::raster::WindowVertex;

namespace {

const std::vector<VertexStageVector>& vectors() {
  static const std::vector<VertexStageVector> v = recode::kit::vertexStageVectors();
  return v;
}

WindowPosition position(const VertexStageVector& v, std::size_t i) {
  return recode::raster::mapToWindow(v.transform.window,
                                     recode::raster::poseVertex(v.transform.pose, v.local[i]));
}

// The vertices of v that `reading` gets wrong.
int wrongVertices(const VertexStageVector& v, VertexStageReading reading) {
  int n = 0;
  for (std::size_t i = 0; i < v.local.size(); ++i) {
    if (!recode::kit::sameBits(recode::kit::vertexStageAs(reading, v.transform, v.local[i]),
                               v.expected[i]))
      ++n;
  }
  return n;
}

struct Catches {
  std::vector<std::string> vectors;  // names of the vectors with a wrong vertex
  int vertices = 0;                  // wrong vertices in all
};

// For each wrong reading, what catches it. Computed once: several cases use it.
const std::map<std::string, Catches>& catchesByReading() {
  static const std::map<std::string, Catches> catches = [] {
    std::map<std::string, Catches> out;
    for (const VertexStageReadingInfo& r : recode::kit::wrongVertexStageReadings()) {
      Catches& c = out[std::string(r.name)];
      for (const VertexStageVector& v : vectors()) {
        const int n = wrongVertices(v, r.reading);
        if (n > 0)
          c.vectors.push_back(v.name);
        c.vertices += n;
      }
    }
    return out;
  }();
  return catches;
}

// The readings caught by fewer than kMinVertexStageCatches of the vectors whose name `keep`
// accepts, as "name (count)", comma-separated ("" when none).
std::string belowThreshold(const std::function<bool(const std::string&)>& keep) {
  std::string below;
  for (const VertexStageReadingInfo& r : recode::kit::wrongVertexStageReadings()) {
    const std::vector<std::string>& names = catchesByReading().at(std::string(r.name)).vectors;
    const auto n = std::count_if(names.begin(), names.end(), keep);
    if (n < kMinVertexStageCatches)
      below += (below.empty() ? "" : ", ") + std::string(r.name) + " (" + std::to_string(n) + ")";
  }
  return below;
}

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

// x 256 is exactly k + 0.5.
bool snapTie(double x) {
  const double scaled = x * 256.0;
  return scaled - std::floor(scaled) == 0.5;
}

// z lies exactly halfway between two neighbouring floats.
bool floatTie(double z) {
  const float nearest = static_cast<float>(z);
  if (static_cast<double>(nearest) == z)
    return false;
  const float other =
      std::nextafter(nearest, static_cast<double>(nearest) < z ? FLT_MAX : -FLT_MAX);
  return (static_cast<double>(nearest) + static_cast<double>(other)) / 2.0 == z;
}

bool isNegativeZero(float f) {
  return std::bit_cast<std::uint32_t>(f) == 0x80000000u;
}

bool powerOfTwo(double x) {
  int exponent = 0;
  return std::frexp(x, &exponent) == 0.5;
}

}  // namespace

TEST_CASE("the vertex stage reproduces every vertex-stage vector bit for bit",
          "[kit][vertex-stage]") {
  REQUIRE(vectors().size() >= 20);
  std::size_t vertices = 0;
  std::set<std::string> names;
  for (const VertexStageVector& v : vectors()) {
    INFO(v.name);
    CHECK(names.insert(v.name).second);
    REQUIRE(v.local.size() == v.expected.size());
    CHECK(v.local.size() >= 6);
    for (std::size_t i = 0; i < v.local.size(); ++i) {
      INFO("vertex " << i);
      CHECK(recode::raster::drawablePosition(position(v, i)));
      CHECK(recode::kit::sameBits(recode::raster::vertexStage(v.transform, v.local[i]),
                                  v.expected[i]));
      CHECK(recode::kit::sameBits(
          recode::kit::vertexStageAs(VertexStageReading::Contract, v.transform, v.local[i]),
          v.expected[i]));
    }
    vertices += v.local.size();
  }
  CHECK(vertices >= 200);
  CHECK(vertices <= 500);
}

TEST_CASE(
    "every wrong reading of the vertex stage gets at least kMinVertexStageCatches vectors "
    "wrong",
    "[kit][vertex-stage]") {
  std::ostringstream summary;
  summary << "vertex-stage vectors (of " << vectors().size()
          << ") and vertices catching each wrong reading (at least " << kMinVertexStageCatches
          << " vectors each):";
  for (const VertexStageReadingInfo& r : recode::kit::wrongVertexStageReadings()) {
    const Catches& c = catchesByReading().at(std::string(r.name));
    summary << "\n  " << r.name << ": " << c.vectors.size() << " vectors, " << c.vertices
            << " vertices";
  }
  WARN(summary.str());
  // On failure Catch prints the readings below the threshold, with their counts.
  CHECK(belowThreshold([](const std::string&) { return true; }) == "");
}

TEST_CASE("without their special cases the vertex-stage vectors miss readings",
          "[kit][vertex-stage]") {
  // The check can fail: the rotated and far blocks alone (random and aimed vertices) catch
  // neither a snapped -0 turned into +0 nor a subnormal depth flushed to zero.
  const std::string below = belowThreshold([](const std::string& name) {
    return startsWith(name, "rotated_") || startsWith(name, "far_");
  });
  CHECK(below == "snap_through_integer (0), depth_flush_subnormal (0)");
}

TEST_CASE("the vertex-stage vectors contain the cases they claim", "[kit][vertex-stage]") {
  // Vectors (not vertices) holding each case.
  std::map<std::string, int> cases;
  for (const VertexStageVector& v : vectors()) {
    const recode::raster::WindowMapping& m = v.transform.window;
    std::set<std::string> has;
    has.insert(std::string("along ") + (m.axes == std::array<int, 3>{0, 1, 2}   ? "z"
                                        : m.axes == std::array<int, 3>{1, 2, 0} ? "x"
                                        : m.axes == std::array<int, 3>{2, 0, 1} ? "y"
                                                                                : "?"));
    const std::array<double, 9>& l = v.transform.pose.linear;
    if (std::all_of(l.begin(), l.end(), [](double e) { return e != 0.0 && std::fabs(e) != 1.0; }))
      has.insert("rotation");
    // The translation at least 100 times the block's extent in every coordinate.
    double extent = 0.0;
    for (const std::array<double, 3>& p : v.local) {
      for (const double c : p)
        extent = std::max(extent, std::fabs(c));
    }
    const std::array<double, 3>& t = v.transform.pose.translation;
    if (std::all_of(t.begin(), t.end(), [&](double c) { return std::fabs(c) > 100.0 * extent; }))
      has.insert("far");
    if (!powerOfTwo(m.urange) && !powerOfTwo(m.vrange) && !powerOfTwo(m.depthRange) &&
        !powerOfTwo(m.width) && !powerOfTwo(m.height))
      has.insert("no power of two");
    for (std::size_t i = 0; i < v.local.size(); ++i) {
      const WindowPosition p = position(v, i);
      if (snapTie(p.x) || snapTie(p.y))
        has.insert("snap tie");
      if (isNegativeZero(v.expected[i].x))
        has.insert("-0 x");
      if (isNegativeZero(v.expected[i].y))
        has.insert("-0 y");
      if (floatTie(p.z))
        has.insert("z tie");
      if (p.z > 0.0 && p.z < static_cast<double>(FLT_MIN))
        has.insert("subnormal z");
    }
    for (const std::string& c : has)
      ++cases[c];
  }
  std::ostringstream summary;
  summary << "vertex-stage vectors holding each case:";
  for (const auto& [c, n] : cases)
    summary << "\n  " << c << ": " << n;
  WARN(summary.str());
  for (const char* c : {"along x", "along y", "along z", "rotation", "far", "no power of two",
                        "snap tie", "-0 x", "-0 y", "z tie", "subnormal z"}) {
    INFO(c);
    CHECK(cases[c] >= 3);
  }
  CHECK(cases["along ?"] == 0);
}

TEST_CASE("hexDouble writes Python's float.hex()", "[kit][vertex-stage]") {
  using recode::kit::hexDouble;
  CHECK(hexDouble(1.0) == "0x1.0000000000000p+0");
  CHECK(hexDouble(3.0) == "0x1.8000000000000p+1");
  CHECK(hexDouble(-0.1) == "-0x1.999999999999ap-4");
  CHECK(hexDouble(0.0) == "0x0.0p+0");
  CHECK(hexDouble(-0.0) == "-0x0.0p+0");
  CHECK(hexDouble(0x1p-1074) == "0x0.0000000000001p-1022");
  CHECK(hexDouble(DBL_MAX) == "0x1.fffffffffffffp+1023");
  CHECK(hexDouble(1000.0) == "0x1.f400000000000p+9");
  CHECK_THROWS(hexDouble(INFINITY));
}

TEST_CASE("data/golden/vertex-stage.jsonl is what the generator writes", "[kit][vertex-stage]") {
  const std::string text = recode::kit::vertexStageGoldenText(vectors());
  // Deterministic: a second generation writes the same bytes.
  CHECK(recode::kit::vertexStageGoldenText(recode::kit::vertexStageVectors()) == text);
  const auto path = std::filesystem::path(RECODE_DATA_DIR) / "golden" / "vertex-stage.jsonl";
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream onDisk;
  onDisk << in.rdbuf();
  // On a deliberate change: build/tests/raster/recode-write-vertex-stage-golden FILE.
  INFO("regenerate with recode-write-vertex-stage-golden " << path.string());
  CHECK(onDisk.str() == text);
}
