// The conformance kit discriminates: every deliberately wrong variant of the reference model
// (recode/kit/variants.hpp) gets at least kMinCatches vectors of data/golden/kit/ wrong, so a
// back end that makes one of those mistakes cannot pass the kit, and no variant hangs on a
// single vector. The test prints each variant with the number of vectors that catch it. The
// second case shows the check can fail: without the depth_arithmetic family, nine readings of
// the depth arithmetic go uncaught.

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/kit/reference_model.hpp"
#include "recode/kit/variants.hpp"
#include "recode/raster/golden.hpp"

using namespace recode::raster;
using recode::kit::kMinCatches;
using recode::kit::ReferenceModel;
using recode::kit::Variant;
using recode::kit::VariantInfo;

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

// For each wrong variant, the stems of the vectors it fails. Computed once: both cases use it.
const std::map<std::string, std::vector<std::string>>& catchesByVariant() {
  static const std::map<std::string, std::vector<std::string>> catches = [] {
    std::map<std::string, std::vector<std::string>> out;
    const std::vector<NamedVector> vectors = kitVectors();
    for (const VariantInfo& v : recode::kit::wrongVariants()) {
      std::vector<std::string>& stems = out[std::string(v.name)];
      for (const NamedVector& n : vectors) {
        if (fails(n.golden, v.variant))
          stems.push_back(n.stem);
      }
    }
    return out;
  }();
  return catches;
}

// The variants caught by fewer than kMinCatches of the vectors whose stem `keep` accepts, as
// "name (count)", comma-separated ("" when none).
template <class Keep>
std::string belowThreshold(Keep keep) {
  std::string below;
  for (const VariantInfo& v : recode::kit::wrongVariants()) {
    const std::vector<std::string>& stems = catchesByVariant().at(std::string(v.name));
    const auto n = std::count_if(stems.begin(), stems.end(), keep);
    if (n < kMinCatches)
      below += (below.empty() ? "" : ", ") + std::string(v.name) + " (" + std::to_string(n) + ")";
  }
  return below;
}

}  // namespace

TEST_CASE("every wrong variant of the contract fails at least kMinCatches kit vectors", "[kit]") {
  const std::vector<NamedVector> vectors = kitVectors();
  REQUIRE(vectors.size() >= 200);
  // The contract itself passes all of them (golden_test.cpp checks the bytes too).
  for (const NamedVector& n : vectors) {
    INFO(n.stem);
    CHECK_FALSE(fails(n.golden, Variant::Contract));
  }
  // The summary, one variant a line, printed whether the case passes or not.
  std::ostringstream summary;
  summary << "kit vectors catching each wrong variant (at least " << kMinCatches << " each):";
  for (const VariantInfo& v : recode::kit::wrongVariants()) {
    summary << "\n  " << v.name << ": " << catchesByVariant().at(std::string(v.name)).size();
  }
  WARN(summary.str());
  // On failure Catch prints the variants below the threshold, with their counts.
  CHECK(belowThreshold([](const std::string&) { return true; }) == "");
}

TEST_CASE("the discrimination check fails when a family is dropped", "[kit]") {
  // Without depth_arithmetic, the readings that change a depth by an ulp only where the exact
  // value is a tie, and that no other family is built to find, go uncaught.
  const std::string below = belowThreshold(
      [](const std::string& stem) { return stem.rfind("depth_arithmetic_", 0) != 0; });
  CHECK(below ==
        "anchor_pixel_centre (0), slope_divide_terms (0), eval_y_first (0), "
        "eval_offsets_first (0), fma_slope_x_left (0), fma_slope_x_right (0), "
        "fma_slope_y_left (0), fma_slope_y_right (0), fma_eval_x (0)");
}
