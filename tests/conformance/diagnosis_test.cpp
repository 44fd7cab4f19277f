// How the diagnosis reads a bad pixel's stage from its history. A back end that draws nothing, or
// too little, is told which event of the pixel's history its buffers never saw (a fragment:
// coverage; a clear: clear), never that a depth test went the other way or a depth value is
// off; a depth test that really went the other way, leaving a trace in the buffers, is still
// told "depth test".
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "recode/conformance/suite.hpp"

using namespace recode::conformance;
namespace raster = recode::raster;
namespace cmd = recode::raster::cmd;
using raster::CompareFunc;

namespace {

const std::vector<SuiteVector>& goldenSet() {
  static const std::vector<SuiteVector> all = goldenVectors(RECODE_DATA_DIR "/golden");
  return all;
}

// The first answer of many a new back end: the fresh buffers, no command applied.
class FreshBuffers final : public Backend {
 public:
  std::string name() const override { return "fresh buffers"; }
  Answer run(const raster::CommandStream& s) override {
    const std::size_t n = static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height);
    return {std::vector<std::uint32_t>(n, 16777215u), std::vector<std::uint8_t>(n, 0), {}};
  }
};

bool noTrace(const PixelExplanation& e) {
  return e.rule == "no trace of a fragment" || e.rule == "no trace of a clear";
}

// One triangle over the whole of a frame up to 8 x 8, at depth z, no sample on an edge.
cmd::Draw cover(float z) {
  return {{{-1.0f, -1.0f, z}, {20.0f, -1.0f, z}, {-1.0f, 20.0f, z}}, {0, 1, 2}};
}

// The reference's answer with every depth test compared by `func` instead.
Answer withDepthFunc(raster::CommandStream s, CompareFunc func) {
  for (raster::Command& c : s.commands) {
    if (auto* d = std::get_if<cmd::DepthFunc>(&c))
      d->func = func;
  }
  return referenceAnswer(s);
}

// The explanation of pixel (1, 1), which must be bad.
PixelExplanation explainOnePixel(const raster::CommandStream& s, const Answer& got) {
  const Answer expected = referenceAnswer(s);
  for (const BadPixel& p : badPixels(s, expected, got, SIZE_MAX)) {
    if (p.x == 1 && p.y == 1)
      return explainPixel(s, p, {});
  }
  FAIL("pixel (1, 1) is not bad");
  return {};
}

}  // namespace

TEST_CASE("fresh buffers fail every golden vector at coverage or a clear", "[diagnosis]") {
  FreshBuffers fresh;
  SuiteOptions o;
  o.explainLimit = 4;  // with the wrong readings, which match many an untouched pixel
  o.classify = false;
  const SuiteReport r = runSuite(fresh, goldenSet(), o);
  // Every vector draws or clears something.
  CHECK(r.count(Status::Failed) == static_cast<int>(goldenSet().size()));
  CHECK(r.behavesLike.empty());
  int clears = 0;
  for (const VectorReport& v : r.vectors) {
    INFO(v.name);
    REQUIRE(v.stage.has_value());
    CHECK((*v.stage == Stage::Coverage || *v.stage == Stage::Clear));
    clears += *v.stage == Stage::Clear ? 1 : 0;
    for (const PixelExplanation& e : v.explained) {
      INFO("pixel (" << e.pixel.x << ", " << e.pixel.y << "): " << toString(e.stage) << ": "
                     << e.why);
      CHECK(noTrace(e));
      CHECK_THAT(e.why, Catch::StartsWith("the back end's buffers show no trace of the "));
    }
  }
  // Vectors that clear depth or stencil to another value first miss the clear.
  CHECK(clears > 0);
}

TEST_CASE("no bad pixel of fresh buffers reads as a depth test or a depth value", "[diagnosis]") {
  FreshBuffers fresh;
  long long pixels = 0;
  for (const SuiteVector& v : goldenSet()) {
    const raster::CommandStream& s = v.golden.stream;
    const Answer expected{v.golden.depth, v.golden.stencil, {}};
    for (const BadPixel& p : badPixels(s, expected, fresh.run(s), SIZE_MAX)) {
      const PixelExplanation e = explainPixel(s, p, {});
      ++pixels;
      if (!noTrace(e) || e.stage == Stage::DepthTest || e.stage == Stage::DepthValue) {
        FAIL_CHECK(v.name << " pixel (" << p.x << ", " << p.y << "): " << toString(e.stage) << " ("
                          << e.rule << "): " << e.why);
      }
    }
  }
  CHECK(pixels == 93082);  // every pixel some command changes
}

TEST_CASE("the missed event is the latest one the back end's values come before", "[diagnosis]") {
  // Depth cleared to 0.5, a triangle at 0.25 drawn, then one at 0.75 that the depth test keeps
  // out.
  const raster::CommandStream s{
      4, 4, {cmd::ClearDepth{0.5}, cmd::DepthFunc{CompareFunc::Less}, cover(0.25f), cover(0.75f)}};
  // Fresh buffers: the clear never ran.
  FreshBuffers fresh;
  const PixelExplanation none = explainOnePixel(s, fresh.run(s));
  CHECK(none.stage == Stage::Clear);
  CHECK(none.rule == "no trace of a clear");
  CHECK(none.why ==
        "the back end's buffers show no trace of the depth clear of command 0: its depth and "
        "stencil are the values before it");
  // The clear but no draw: the first triangle's fragment is missing.
  const raster::CommandStream clearOnly{4, 4, {cmd::ClearDepth{0.5}}};
  const PixelExplanation cleared = explainOnePixel(s, referenceAnswer(clearOnly));
  CHECK(cleared.stage == Stage::Coverage);
  CHECK(cleared.why ==
        "the back end's buffers show no trace of the fragment of triangle 0 of draw 0 (command "
        "2): its depth and stencil are the values before it");
}

TEST_CASE("a depth test that went the other way and left a trace is told so", "[diagnosis]") {
  SECTION("a fragment the contract's test keeps out is in the back end's depth") {
    const raster::CommandStream s{
        4,
        4,
        {cmd::ClearDepth{1.0}, cmd::DepthFunc{CompareFunc::Less}, cover(0.25f), cover(0.75f)}};
    const PixelExplanation e = explainOnePixel(s, withDepthFunc(s, CompareFunc::Always));
    CHECK(e.stage == Stage::DepthTest);
    CHECK(e.rule == "a depth the history holds");
    CHECK_THAT(e.why, Catch::Contains("triangle 0 of draw 1 (command 3)"));
  }
  SECTION("a fragment kept out by mistake leaves its depth-fail op in the stencil") {
    raster::StencilOps ops;
    ops.depthFail = raster::StencilOp::Incr;
    const raster::CommandStream s{4,
                                  4,
                                  {cmd::ClearDepth{1.0}, cmd::DepthFunc{CompareFunc::Less},
                                   cmd::StencilOpsCmd{raster::Face::Both, ops}, cover(0.5f)}};
    const PixelExplanation e = explainOnePixel(s, withDepthFunc(s, CompareFunc::GEqual));
    CHECK(e.stage == Stage::DepthTest);
    CHECK(e.rule == "a depth the history holds");
  }
  SECTION("a fragment kept out by mistake, its ops keeping the stencil, leaves no trace") {
    // The pixel is then the one a back end that never drew the triangle leaves: read at the
    // first stage that can leave it, coverage.
    const raster::CommandStream s{
        4, 4, {cmd::ClearDepth{1.0}, cmd::DepthFunc{CompareFunc::Less}, cover(0.5f)}};
    const PixelExplanation e = explainOnePixel(s, withDepthFunc(s, CompareFunc::GEqual));
    CHECK(e.stage == Stage::Coverage);
    CHECK(e.rule == "no trace of a fragment");
  }
}
