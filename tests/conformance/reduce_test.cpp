// Reduction of failing vectors: kit vectors that five wrong readings from five stages get wrong
// shrink to at most 4 draws and 8 triangles that still fail at the same pixel, in the same
// buffers, at the same stage, with the reference's buffers and a passing twin one step away.
#include <algorithm>
#include <catch2/catch.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/conformance/reduce.hpp"
#include "recode/kit/generator.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"

using namespace recode;
using namespace recode::conformance;
using kit::Variant;
using raster::CommandStream;
namespace cmd = raster::cmd;

namespace Catch {
template <>
struct StringMaker<std::optional<FailureSignature>> {
  static std::string convert(const std::optional<FailureSignature>& s) {
    if (!s)
      return "passes";
    if (s->refused)
      return "refused";
    return "(" + std::to_string(s->x) + ", " + std::to_string(s->y) + ")" +
           (s->depth ? " depth" : "") + (s->stencil ? " stencil" : "") + " stage " +
           std::string(toString(s->stage));
  }
};
template <>
struct StringMaker<FailureSignature> {
  static std::string convert(const FailureSignature& s) {
    return StringMaker<std::optional<FailureSignature>>::convert(s);
  }
};
}  // namespace Catch

namespace {

raster::GoldenVector kitVector(const std::string& name) {
  return raster::readGolden(std::string(RECODE_DATA_DIR) + "/golden/kit/" + name);
}

std::optional<FailureSignature> signatureOn(const CommandStream& s, Backend& backend) {
  return signatureOf(s, referenceAnswer(s), backend.run(s));
}

std::string json(const raster::Command& c) {
  return raster::commandStreamToJson({1, 1, {c}});
}

bool sameCommands(const std::vector<raster::Command>& a, const std::vector<raster::Command>& b) {
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (json(a[i]) != json(b[i]))
      return false;
  }
  return true;
}

bool sameVertex(const raster::WindowVertex& a, const raster::WindowVertex& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

// The triangles' vertices in index order: what a draw draws, whatever its vertex list holds.
std::vector<raster::WindowVertex> drawn(const cmd::Draw& d) {
  std::vector<raster::WindowVertex> out;
  for (const std::uint32_t i : d.indices)
    out.push_back(d.vertices[i]);
  return out;
}

bool sameDrawn(const cmd::Draw& a, const cmd::Draw& b) {
  const auto va = drawn(a), vb = drawn(b);
  return va.size() == vb.size() && std::equal(va.begin(), va.end(), vb.begin(), sameVertex);
}

// Whether the twin is the minimal vector after one step of the reduction: the frame shrunk, a
// run of commands or of one draw's triangles removed, unreferenced vertices dropped, one vertex
// coordinate or depth moved, or one state command changed.
bool oneStepApart(const CommandStream& m, const CommandStream& t) {
  if (m.width != t.width || m.height != t.height)
    return t.width <= m.width && t.height <= m.height && sameCommands(m.commands, t.commands);
  if (t.commands.size() < m.commands.size()) {
    const std::size_t removed = m.commands.size() - t.commands.size();
    for (std::size_t b = 0; b + removed <= m.commands.size(); ++b) {
      std::vector<raster::Command> rest = m.commands;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(b),
                 rest.begin() + static_cast<std::ptrdiff_t>(b + removed));
      if (sameCommands(rest, t.commands))
        return true;
    }
    return false;
  }
  if (t.commands.size() != m.commands.size())
    return false;
  std::vector<std::size_t> differ;
  for (std::size_t i = 0; i < m.commands.size(); ++i) {
    if (json(m.commands[i]) != json(t.commands[i]))
      differ.push_back(i);
  }
  if (differ.size() != 1)
    return false;
  const raster::Command& a = m.commands[differ[0]];
  const raster::Command& b = t.commands[differ[0]];
  if (a.index() != b.index())
    return false;
  const auto* da = std::get_if<cmd::Draw>(&a);
  if (da == nullptr)
    return true;  // one state command moved towards its default
  const auto& db = std::get<cmd::Draw>(b);
  if (db.vertices.size() < da->vertices.size())
    return sameDrawn(*da, db);
  if (db.vertices.size() != da->vertices.size())
    return false;
  if (db.indices == da->indices) {
    int moved = 0;
    for (std::size_t v = 0; v < da->vertices.size(); ++v) {
      const auto& p = da->vertices[v];
      const auto& q = db.vertices[v];
      moved += (p.x != q.x) + (p.y != q.y) + (p.z != q.z);
    }
    return moved == 1;
  }
  if (db.indices.size() >= da->indices.size() || db.indices.size() % 3 != 0)
    return false;
  const std::size_t removed = da->indices.size() - db.indices.size();
  for (std::size_t from = 0; from + removed <= da->indices.size(); from += 3) {
    std::vector<std::uint32_t> rest = da->indices;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(from),
               rest.begin() + static_cast<std::ptrdiff_t>(from + removed));
    if (rest == db.indices)
      return true;
  }
  return false;
}

void requireReferenceBuffers(const raster::GoldenVector& g) {
  raster::CpuDevice device(g.stream.width, g.stream.height);
  raster::replay(g.stream.commands, device);
  CHECK(std::equal(g.depth.begin(), g.depth.end(), device.depthBuffer().begin(),
                   device.depthBuffer().end()));
  CHECK(std::equal(g.stencil.begin(), g.stencil.end(), device.stencilBuffer().begin(),
                   device.stencilBuffer().end()));
}

int trianglesOf(const CommandStream& s, int* draws) {
  int t = 0;
  *draws = 0;
  for (const raster::Command& c : s.commands) {
    if (const auto* d = std::get_if<cmd::Draw>(&c)) {
      ++*draws;
      t += static_cast<int>(d->indices.size() / 3);
    }
  }
  return t;
}

}  // namespace

TEST_CASE("the signature is the first bad pixel in scan order, its buffers and stage", "[reduce]") {
  CommandStream s{4, 3, {cmd::ClearDepth{0.5}}};
  const Answer expected = referenceAnswer(s);
  CHECK_FALSE(signatureOf(s, expected, expected));

  Answer got = expected;
  got.depth[2 * 4 + 3] = 7;  // pixel (3, 2)
  got.depth[1 * 4 + 2] = 9;  // pixel (2, 1): first in scan order
  got.stencil[1 * 4 + 2] = 1;
  const auto sig = signatureOf(s, expected, got);
  REQUIRE(sig);
  CHECK(sig->x == 2);
  CHECK(sig->y == 1);
  CHECK(sig->depth);
  CHECK(sig->stencil);
  CHECK_FALSE(sig->refused);
  CHECK(sig->stage == Stage::Clear);  // only a clear reaches the pixel

  Answer refused;
  refused.refused = "no";
  const auto r = signatureOf(s, expected, refused);
  REQUIRE(r);
  CHECK(r->refused);
  CHECK(r->stage == Stage::Validation);
}

TEST_CASE("failures of five wrong readings reduce to small vectors that fail the same way",
          "[reduce]") {
  struct Case {
    Variant variant;
    const char* file;
  };
  // One reading per stage, each on one of the larger kit vectors it fails.
  const Case cases[] = {
      {Variant::TopLeftFill, "shared_edges_0.json"},          // coverage, 40 triangles
      {Variant::FmaPlane, "depth_arithmetic_45.json"},        // depth value
      {Variant::QuantiseHalfUp, "depth_arithmetic_50.json"},  // quantisation
      {Variant::IncrWraps, "compare_ops_6.json"},             // stencil, 84 commands
      {Variant::ClearIgnoresScissor, "compare_ops_7.json"},   // clears
      {Variant::StrictLimits, "depth_arithmetic_1.json"},     // validation: a refusal
  };
  for (const Case& c : cases) {
    DYNAMIC_SECTION(kit::variantName(c.variant) << " on " << c.file) {
      const raster::GoldenVector original = kitVector(c.file);
      ModelBackend wrong(c.variant);
      const auto signature = signatureOn(original.stream, wrong);
      REQUIRE(signature);  // the kit says this reading fails it

      const Reduction r = reduce(original.stream, wrong);
      int draws = 0;
      const int triangles = trianglesOf(r.minimal.stream, &draws);
      CAPTURE(r.draws, r.triangles, r.backendRuns, r.minimal.stream.commands.size(),
              r.minimal.stream.width, r.minimal.stream.height, r.minimal.description,
              r.passingTwin.has_value());
      CHECK(r.signature == *signature);
      CHECK(r.draws == draws);
      CHECK(r.triangles == triangles);
      CHECK(r.draws <= 4);
      CHECK(r.triangles <= 8);
      CHECK(r.backendRuns <= ReduceOptions{}.maxBackendRuns);
      CHECK(r.minimal.stream.commands.size() <= original.stream.commands.size());
      CHECK(signatureOn(r.minimal.stream, wrong) == signature);
      requireReferenceBuffers(r.minimal);
      CHECK(ModelBackend(Variant::Contract).run(r.minimal.stream) ==
            Answer{r.minimal.depth, r.minimal.stencil, {}});
      CHECK(r.minimal.description.find("Reduced") != std::string::npos);
      CHECK(r.minimal.description.find(wrong.name()) != std::string::npos);
      // Ready to commit: the file reader, stricter than the devices, takes it back unchanged.
      const std::string text = raster::goldenToJson(r.minimal, raster::GoldenLayout::Rows);
      CHECK(raster::goldenToJson(raster::goldenFromJson(text, "minimal"),
                                 raster::GoldenLayout::Rows) == text);

      if (r.passingTwin) {
        const raster::GoldenVector& twin = *r.passingTwin;
        CAPTURE(twin.description);
        CHECK(wrong.run(twin.stream) == referenceAnswer(twin.stream));
        CHECK(oneStepApart(r.minimal.stream, twin.stream));
        requireReferenceBuffers(twin);
        CHECK(twin.description.find("Passing twin") != std::string::npos);
      }
      // Every reading with a pixel has a twin here: moving a vertex or dropping the draw that
      // makes the difference passes.
      if (!signature->refused)
        CHECK(r.passingTwin);
    }
  }
}

TEST_CASE("the reduction is deterministic and keeps to its budget", "[reduce]") {
  const raster::GoldenVector original = kitVector("shared_edges_0.json");
  ModelBackend wrong(Variant::TopLeftFill);
  const Reduction a = reduce(original.stream, wrong);
  const Reduction b = reduce(original.stream, wrong);
  CHECK(raster::goldenToJson(a.minimal) == raster::goldenToJson(b.minimal));
  REQUIRE(a.passingTwin.has_value() == b.passingTwin.has_value());
  if (a.passingTwin)
    CHECK(raster::goldenToJson(*a.passingTwin) == raster::goldenToJson(*b.passingTwin));
  CHECK(a.backendRuns == b.backendRuns);

  // Cut short, it still hands back a vector that fails the same way.
  ReduceOptions few;
  few.maxBackendRuns = 6;
  const Reduction c = reduce(original.stream, wrong, few);
  CHECK(c.backendRuns <= 6);
  CHECK(c.signature == a.signature);
  CHECK(signatureOn(c.minimal.stream, wrong) == a.signature);
  requireReferenceBuffers(c.minimal);
}

TEST_CASE("reduce refuses a stream the back end does not fail", "[reduce]") {
  const raster::GoldenVector original = kitVector("shared_edges_0.json");
  ModelBackend contract(Variant::Contract);
  CHECK_THROWS_AS(reduce(original.stream, contract), std::invalid_argument);
  // A wrong reading that this vector does not catch passes it too.
  ModelBackend stencilOnly(Variant::IncrWraps);
  REQUIRE_FALSE(signatureOn(original.stream, stencilOnly));
  CHECK_THROWS_AS(reduce(original.stream, stencilOnly), std::invalid_argument);
}

TEST_CASE("long and random streams reduce too", "[reduce]") {
  // Five kit vectors one after the other on the largest of their frames: state left by one
  // part reaches the next, and most of the stream is beside the point.
  CommandStream joined;
  for (const char* name : {"masks_0.json", "anchor_0.json", "depth_arithmetic_45.json",
                           "compare_ops_7.json", "shared_edges_0.json"}) {
    const raster::GoldenVector g = kitVector(name);
    joined.width = std::max(joined.width, g.stream.width);
    joined.height = std::max(joined.height, g.stream.height);
    joined.commands.insert(joined.commands.end(), g.stream.commands.begin(),
                           g.stream.commands.end());
  }
  std::vector<std::pair<std::string, CommandStream>> candidates{{"joined", joined}};
  for (int i = 0; i < 60; ++i) {
    kit::KitVector v = kit::randomKitStream(11, i);  // recode conform --random 60 --seed 11
    candidates.emplace_back(v.name, std::move(v.golden.stream));
  }
  for (const Variant variant : {Variant::TopLeftFill, Variant::FmaPlane, Variant::QuantiseHalfUp,
                                Variant::IncrWraps, Variant::ClearIgnoresScissor}) {
    ModelBackend wrong(variant);
    // The joined stream where the reading fails it, and the first random stream it fails.
    int reduced = 0, random = 0;
    for (const auto& [name, stream] : candidates) {
      if (name != "joined" && random == 1)
        break;
      const auto signature = signatureOn(stream, wrong);
      if (!signature)
        continue;
      random += name != "joined";
      ++reduced;
      CAPTURE(kit::variantName(variant), name);
      const Reduction r = reduce(stream, wrong);
      CAPTURE(r.minimal.description);
      CHECK(r.draws <= 4);
      CHECK(r.triangles <= 8);
      CHECK(signatureOn(r.minimal.stream, wrong) == signature);
      requireReferenceBuffers(r.minimal);
      if (r.passingTwin) {
        CHECK(wrong.run(r.passingTwin->stream) == referenceAnswer(r.passingTwin->stream));
        CHECK(oneStepApart(r.minimal.stream, r.passingTwin->stream));
      }
    }
    CAPTURE(kit::variantName(variant));
    CHECK(random == 1);
  }
}
