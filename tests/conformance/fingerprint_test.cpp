// The fingerprint names the freedom a back end takes: the kit's model with one reading of a
// freedom is fingerprinted as that reading on its trait and as the contract on the others.

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "recode/conformance/backend.hpp"
#include "recode/conformance/fingerprint.hpp"
#include "recode/conformance/suite.hpp"

using namespace recode;
using namespace recode::conformance;

namespace {

std::vector<FingerprintTrait> fingerprintOf(kit::Variant v) {
  static const std::vector<SuiteVector> vectors = goldenVectors(RECODE_DATA_DIR "/golden");
  FingerprintBuilder b;
  ModelBackend model(v);
  for (const SuiteVector& s : vectors) {
    const Answer expected{s.golden.depth, s.golden.stencil, ""};
    b.add(s.name, s.golden.stream, expected, model.run(s.golden.stream));
  }
  return b.traits();
}

std::string taken(const FingerprintTrait& t) {
  return t.taken < 0 ? "none" : t.candidates[static_cast<std::size_t>(t.taken)].name;
}

}  // namespace

TEST_CASE("the fingerprint names the reading of each freedom a model takes") {
  struct Case {
    kit::Variant variant;
    std::size_t trait;  // tie rule, sub-pixel precision, depth arithmetic, 24-bit conversion
    const char* name;
  };
  const Case cases[] = {
      {kit::Variant::TopLeftFill, 0, "top_left_fill"},
      {kit::Variant::SubPixel4Nearest, 1, "subpixel_4_nearest"},
      {kit::Variant::SubPixel6Nearest, 1, "subpixel_6_nearest"},
      {kit::Variant::FloatPlane, 2, "float_plane"},
      {kit::Variant::QuantiseTruncate, 3, "quantise_truncate"},
  };
  for (const Case& c : cases) {
    const std::vector<FingerprintTrait> traits = fingerprintOf(c.variant);
    REQUIRE(traits.size() == 4);
    INFO(c.name << "\n" << describe(traits));
    CHECK(taken(traits[c.trait]) == c.name);
  }
}

TEST_CASE("the contract's own answers are fingerprinted as the contract on every freedom") {
  const std::vector<FingerprintTrait> traits = fingerprintOf(kit::Variant::Contract);
  INFO(describe(traits));
  for (const FingerprintTrait& t : traits)
    CHECK(taken(t) == "contract");
}
