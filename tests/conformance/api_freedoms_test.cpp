// What the graphics APIs allow (api_freedoms.hpp) is sound and not vacuous: the contract and
// every reading of the kit that takes one of the APIs' freedoms lie inside the allowed states
// at every pixel of every golden vector, and every reading that breaks a rule the APIs fix
// falls outside them somewhere.

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "recode/conformance/api_freedoms.hpp"
#include "recode/conformance/backend.hpp"
#include "recode/conformance/suite.hpp"

using namespace recode;
using namespace recode::conformance;

namespace {

const std::vector<SuiteVector>& vectors() {
  static const std::vector<SuiteVector> all = goldenVectors(RECODE_DATA_DIR "/golden");
  return all;
}

const AllowedFrame& allowedFor(std::size_t i) {
  static std::vector<AllowedFrame> frames;
  if (frames.empty())
    for (const SuiteVector& v : vectors())
      frames.push_back(allowedByApis(v.golden.stream));
  return frames[i];
}

// The pixels of `answer` outside the allowed states (all of them for a refusal).
// `where` gets the first such pixel and its values.
long long outside(const AllowedFrame& frame, const Answer& answer, std::string* where = nullptr) {
  if (answer.wasRefused())
    return static_cast<long long>(frame.pixels.size());
  long long n = 0;
  for (std::size_t p = 0; p < frame.pixels.size(); ++p) {
    const AllowedPixel& a = frame.pixels[p];
    if (a.allows(answer.depth[p], answer.stencil[p]))
      continue;
    if (n++ == 0 && where)
      *where = "pixel (" + std::to_string(p % static_cast<std::size_t>(frame.width)) + ", " +
               std::to_string(p / static_cast<std::size_t>(frame.width)) + "): depth " +
               std::to_string(answer.depth[p]) + ", stencil " + std::to_string(answer.stencil[p]) +
               "; allowed depths " + std::to_string(a.depthMin()) + " .. " +
               std::to_string(a.depthMax()) + " in " + std::to_string(a.states.size()) + " states";
  }
  return n;
}

std::vector<kit::VariantInfo> everyReading() {
  std::vector<kit::VariantInfo> out(kit::wrongVariants().begin(), kit::wrongVariants().end());
  out.insert(out.end(), kit::subPixelVariants().begin(), kit::subPixelVariants().end());
  return out;
}

}  // namespace

TEST_CASE("the contract's own answer is allowed at every pixel of every golden vector") {
  long long bad = 0;
  for (std::size_t i = 0; i < vectors().size(); ++i) {
    const raster::GoldenVector& g = vectors()[i].golden;
    const long long n = outside(allowedFor(i), Answer{g.depth, g.stencil, ""});
    if (n != 0)
      UNSCOPED_INFO(vectors()[i].name << ": " << n << " pixels outside");
    bad += n;
  }
  CHECK(bad == 0);
}

TEST_CASE("every reading that takes an API freedom stays inside the allowed states") {
  for (const kit::VariantInfo& reading : everyReading()) {
    if (!freedomOf(reading.variant))
      continue;
    long long bad = 0;
    std::string first;
    ModelBackend model(reading.variant);
    for (std::size_t i = 0; i < vectors().size(); ++i) {
      std::string where;
      const long long n = outside(allowedFor(i), model.run(vectors()[i].golden.stream), &where);
      if (n != 0 && first.empty())
        first = vectors()[i].name + " " + where;
      bad += n;
    }
    INFO(reading.name << ": first outside in " << first);
    CHECK(bad == 0);
  }
}

TEST_CASE("every reading that breaks a rule the APIs fix falls outside on some vector") {
  int forbidden = 0;
  for (const kit::VariantInfo& reading : everyReading()) {
    if (freedomOf(reading.variant))
      continue;
    ++forbidden;
    ModelBackend model(reading.variant);
    long long bad = 0;
    for (std::size_t i = 0; i < vectors().size() && bad == 0; ++i)
      bad += outside(allowedFor(i), model.run(vectors()[i].golden.stream));
    INFO(reading.name);
    CHECK(bad > 0);
  }
  CHECK(forbidden == 8);  // stencil ops, mask, two clears' masks, scissor, facing, validation
}

TEST_CASE(
    "a sample within sub-pixel reach of a long sliver's edge is open, on the 8-bit grid "
    "it is not") {
  for (std::size_t i = 0; i < vectors().size(); ++i) {
    if (vectors()[i].name != "kit/wide_1.json")
      continue;
    const raster::CommandStream& s = vectors()[i].golden.stream;
    std::vector<OpenChoice> choices;
    const AllowedPixel open = allowedAt(s, 3876, 0, &choices);
    CHECK_FALSE(open.stencilFixed());
    REQUIRE_FALSE(choices.empty());
    CHECK(choices.front().freedom == Freedom::SubPixelPrecision);
    FreedomWidths eightBits;
    eightBits.subPixelBits = 8;
    CHECK(allowedAt(s, 3876, 0, nullptr, eightBits).stencilFixed());
    return;
  }
  FAIL("kit/wide_1.json is not among the golden vectors");
}

TEST_CASE("how much of the kit the APIs fix") {
  // Per family: vectors, those whose stencil and whose depth the APIs fix (the counts
  // docs/conformance.md quotes).
  std::map<std::string, std::array<int, 3>> families;
  int stencil = 0, depth = 0;
  for (std::size_t i = 0; i < vectors().size(); ++i) {
    const std::string& name = vectors()[i].name;
    const std::size_t cut = name.find_last_of('_');
    std::array<int, 3>& f =
        families[name.rfind("kit/", 0) == 0 && cut != std::string::npos ? name.substr(4, cut - 4)
                                                                        : "hand-made"];
    ++f[0];
    if (allowedFor(i).stencilRequired()) {
      ++stencil;
      ++f[1];
    }
    if (allowedFor(i).depthRequired()) {
      ++depth;
      ++f[2];
    }
  }
  for (const auto& [family, n] : families)
    WARN(family << ": " << n[0] << " vectors, stencil fixed in " << n[1] << ", depth in " << n[2]);
  WARN(vectors().size() << " vectors: the APIs fix the stencil of " << stencil
                        << " and the depth of " << depth);
  CHECK(stencil > 0);
}
