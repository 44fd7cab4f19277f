// The suite names what a failing back end behaves like: each of the kit's wrong readings, run as
// a back end, is named (and the contract's model passes and is named nothing).
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "recode/conformance/api_verdict.hpp"
#include "recode/conformance/suite.hpp"

using namespace recode::conformance;
using recode::kit::Variant;

namespace {

const std::vector<SuiteVector>& goldenSet() {
  static const std::vector<SuiteVector> all = goldenVectors(RECODE_DATA_DIR "/golden");
  return all;
}

SuiteOptions quick() {
  SuiteOptions o;
  o.explainLimit = 0;  // naming only: the explanations have their own tests
  o.classify = false;
  return o;
}

}  // namespace

TEST_CASE("the contract's model passes every golden vector and is named nothing", "[naming]") {
  ModelBackend model(Variant::Contract);
  const SuiteReport r = runSuite(model, goldenSet(), quick());
  CHECK(r.passed());
  CHECK(r.count(Status::Passed) == static_cast<int>(goldenSet().size()));
  CHECK(r.behavesLike.empty());
}

TEST_CASE("every wrong reading of the kit, run as a back end, is named", "[naming]") {
  for (const recode::kit::VariantInfo& v : recode::kit::wrongVariants()) {
    ModelBackend model(v.variant);
    const SuiteReport r = runSuite(model, goldenSet(), quick());
    INFO(v.name);
    CHECK_FALSE(r.passed());
    CHECK(std::find(r.behavesLike.begin(), r.behavesLike.end(), v.variant) != r.behavesLike.end());
    // A reading is named alone unless another gives the same bits on every vector.
    CHECK(r.behavesLike.size() <= 2);
  }
}

TEST_CASE("a back end that fails one way no reading has is named by its stages", "[naming]") {
  // The contract, except that pixel (0, 0)'s stencil is inverted after every stream.
  class OnePixelOff final : public Backend {
   public:
    std::string name() const override { return "one pixel off"; }
    Answer run(const recode::raster::CommandStream& s) override {
      Answer a = referenceAnswer(s);
      a.stencil[0] = static_cast<std::uint8_t>(255 - a.stencil[0]);
      return a;
    }
  } backend;
  const std::vector<SuiteVector> some(goldenSet().begin(), goldenSet().begin() + 10);
  SuiteOptions o;
  o.explainLimit = 4;
  const SuiteReport r = runSuite(backend, some, o);
  CHECK(r.count(Status::Failed) == 10);
  CHECK(r.behavesLike.empty());
  for (const VectorReport& v : r.vectors) {
    REQUIRE(v.stage.has_value());
    REQUIRE(v.explained.size() == 1);
    CHECK(v.explained.front().pixel.x == 0);
    CHECK(v.explained.front().pixel.y == 0);
    CHECK_FALSE(v.explained.front().why.empty());
    REQUIRE(v.requirement.has_value());
  }
}

TEST_CASE("a reading is named only when it also agrees where the back end passes", "[naming]") {
  // top_left_fill's answer on the first vector it fails, the contract's everywhere else: its
  // failures alone look like top_left_fill, the vectors it passes say otherwise.
  class WrongOnce final : public Backend {
   public:
    WrongOnce() {
      for (const SuiteVector& v : goldenSet()) {
        if (!(wrong_.run(v.golden.stream) == referenceAnswer(v.golden.stream))) {
          chosen_ = recode::raster::commandStreamToJson(v.golden.stream);
          break;
        }
      }
    }
    std::string name() const override { return "wrong once"; }
    Answer run(const recode::raster::CommandStream& s) override {
      return recode::raster::commandStreamToJson(s) == chosen_ ? wrong_.run(s) : referenceAnswer(s);
    }

   private:
    ModelBackend wrong_{Variant::TopLeftFill};
    std::string chosen_;
  } backend;
  const SuiteReport r = runSuite(backend, goldenSet(), quick());
  CHECK(r.count(Status::Failed) == 1);
  CHECK(r.behavesLike.empty());
}

TEST_CASE(
    "the graphics APIs fix stencil answers away from edges and ties, never the depth bits "
    "of a sloped plane",
    "[requirement]") {
  const auto frame = [](const std::string& name) {
    for (const SuiteVector& v : goldenSet()) {
      if (v.name == name)
        return allowedByApis(v.golden.stream);
    }
    FAIL("no vector " << name);
    return AllowedFrame{};
  };
  const auto has = [](const std::vector<std::string>& list, std::string_view what) {
    return std::find(list.begin(), list.end(), what) != list.end();
  };
  // Stencil ops and compare functions are the APIs' own: most stencil pixels of a compare-ops
  // vector are fixed; its sloped plane's depth bits are not.
  const AllowedFrame ops = frame("kit/compare_ops_0.json");
  const auto fixedStencil = std::count_if(ops.pixels.begin(), ops.pixels.end(),
                                          [](const AllowedPixel& p) { return p.stencilFixed(); });
  CHECK(fixedStencil * 10 > static_cast<long>(ops.pixels.size()) * 9);
  CHECK_FALSE(requirementOf(ops).depth.byGraphicsApis);
  // Samples on shared edges: any consistent tie rule is allowed, so their stencil is ours.
  const Requirement edges = requirementOf(frame("kit/shared_edges_0.json"));
  CHECK_FALSE(edges.stencil.byGraphicsApis);
  CHECK(has(edges.stencil.latitudes, toString(Freedom::TieRule)));
  // A quantisation tie: the rounding (and the interpolation's precision, which reaches further)
  // is the implementation's.
  const Requirement ties = requirementOf(frame("kit/depth_ties_0.json"));
  CHECK_FALSE(ties.depth.byGraphicsApis);
  CHECK((has(ties.depth.latitudes, toString(Freedom::DepthConversion)) ||
         has(ties.depth.latitudes, toString(Freedom::DepthInterpolation))));
  // Wrapping, masks, clears, facing and validation are no freedom of the APIs; the tie rule,
  // float edges, fusion, rounding and the anchor are.
  for (const Variant v :
       {Variant::IncrWraps, Variant::IgnoreValueMask, Variant::ClearIgnoresScissor,
        Variant::SwappedFacing, Variant::StrictLimits})
    CHECK_FALSE(freedomOf(v));
  CHECK(freedomOf(Variant::TopLeftFill) == Freedom::TieRule);
  CHECK(freedomOf(Variant::EdgeFloat) == Freedom::SubPixelPrecision);
  CHECK(freedomOf(Variant::FmaPlane) == Freedom::DepthInterpolation);
  CHECK(freedomOf(Variant::AnchorRotated) == Freedom::DepthInterpolation);
  CHECK(freedomOf(Variant::QuantiseHalfUp) == Freedom::DepthConversion);
}
