// The conformance kit discriminates: every deliberately wrong variant of the reference model
// (recode/kit/variants.hpp) gets at least one vector of data/golden/kit/ wrong, so a back end
// that makes one of those mistakes cannot pass the kit. The second case shows the check can
// fail: without the depth_ties family, rounding ties half up goes unnoticed.

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/kit/reference_model.hpp"
#include "recode/kit/variants.hpp"
#include "recode/raster/golden.hpp"

using namespace recode::raster;
using recode::kit::ReferenceModel;
using recode::kit::Variant;

namespace {

struct NamedVector {
  std::string stem;  // <family>_<index>
  GoldenVector golden;
};

std::vector<NamedVector> kitVectors() {
  std::vector<NamedVector> out;
  const auto dir = std::filesystem::path(RECODE_DATA_DIR) / "golden" / "kit";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".json")
      out.push_back({entry.path().stem().string(), readGolden(entry.path())});
  }
  std::sort(out.begin(), out.end(),
            [](const NamedVector& a, const NamedVector& b) { return a.stem < b.stem; });
  return out;
}

// The variant refuses the vector's stream or produces other bits than it expects.
bool fails(const GoldenVector& g, Variant v) {
  ReferenceModel model(g.stream.width, g.stream.height, v);
  try {
    model.run(g.stream.commands);
  } catch (const std::invalid_argument&) {
    return true;
  }
  return model.depthBuffer() != g.depth || model.stencilBuffer() != g.stencil;
}

// The names of the wrong variants that no vector catches, comma-separated ("" when none).
std::string uncaughtVariants(const std::vector<NamedVector>& vectors) {
  std::string uncaught;
  for (const recode::kit::VariantInfo& v : recode::kit::wrongVariants()) {
    const bool caught = std::any_of(vectors.begin(), vectors.end(), [&](const NamedVector& n) {
      return fails(n.golden, v.variant);
    });
    if (!caught)
      uncaught += (uncaught.empty() ? "" : ", ") + std::string(v.name);
  }
  return uncaught;
}

}  // namespace

TEST_CASE("every wrong variant of the contract fails at least one kit vector", "[kit]") {
  const std::vector<NamedVector> vectors = kitVectors();
  REQUIRE(vectors.size() >= 200);
  // The contract itself passes all of them (golden_test.cpp checks the bytes too).
  for (const NamedVector& n : vectors) {
    INFO(n.stem);
    CHECK_FALSE(fails(n.golden, Variant::Contract));
  }
  // On failure Catch prints the names of the variants no vector catches.
  CHECK(uncaughtVariants(vectors) == "");
}

TEST_CASE("the discrimination check fails when a family is dropped", "[kit]") {
  std::vector<NamedVector> vectors = kitVectors();
  std::erase_if(vectors, [](const NamedVector& n) { return n.stem.rfind("depth_ties_", 0) == 0; });
  REQUIRE(vectors.size() >= 190);
  CHECK(uncaughtVariants(vectors) == "quantise_half_up");
}
