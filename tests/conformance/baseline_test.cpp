// Baselines record each expected failure's stage: a vector that fails at the stage its line
// gives is an expected failure; one that fails at another stage fails the run, and the report
// says what the baseline expected. Also the file's format: NAME,STAGE lines, and a line with a
// name only refused with the file, the line and the form.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "recode/conformance/report.hpp"
#include "recode/conformance/suite.hpp"

using namespace recode::conformance;
using recode::kit::Variant;
namespace fs = std::filesystem;

namespace {

// Four hand-made vectors; the top-left fill rule fails fill_square.json at coverage.
std::vector<SuiteVector> smallSet() {
  std::vector<SuiteVector> out;
  for (const SuiteVector& v : goldenVectors(RECODE_DATA_DIR "/golden")) {
    if (v.name == "fill_square.json" || v.name == "fill_fan.json" ||
        v.name == "depth_less_crossing.json" || v.name == "two_sided_octahedron.json")
      out.push_back(v);
  }
  return out;
}

SuiteOptions withBaseline(Baseline baseline) {
  SuiteOptions o;
  o.explainLimit = 1;
  o.classify = false;
  o.baseline = std::move(baseline);
  return o;
}

const VectorReport& vectorNamed(const SuiteReport& r, const std::string& name) {
  for (const VectorReport& v : r.vectors) {
    if (v.name == name)
      return v;
  }
  FAIL("no vector " << name);
  throw std::logic_error("unreachable");
}

fs::path written(const std::string& name, const std::string& text) {
  const fs::path file = fs::temp_directory_path() / ("recode-baseline-test-" + name);
  std::ofstream(file) << text;
  return file;
}

}  // namespace

TEST_CASE("a failure at the baseline's stage is expected; at another stage it fails the run",
          "[baseline]") {
  ModelBackend topLeft(Variant::TopLeftFill);
  const std::vector<SuiteVector> vectors = smallSet();
  REQUIRE(vectors.size() == 4);

  const SuiteReport unlisted = runSuite(topLeft, vectors, withBaseline({}));
  const VectorReport& square = vectorNamed(unlisted, "fill_square.json");
  REQUIRE(square.status == Status::Failed);
  REQUIRE(square.stage == Stage::Coverage);

  // The baseline the run writes makes every failure of the same run expected.
  const Baseline own = readBaseline(written("own", toBaseline(unlisted)));
  CHECK(own.at("fill_square.json") == Stage::Coverage);
  const SuiteReport expected = runSuite(topLeft, vectors, withBaseline(own));
  CHECK(vectorNamed(expected, "fill_square.json").status == Status::ExpectedFailure);
  CHECK(expected.passed());
  CHECK(expected.changedStages() == 0);

  // The same vector listed with another stage: not expected.
  Baseline changed = own;
  changed["fill_square.json"] = Stage::DepthTest;
  const SuiteReport r = runSuite(topLeft, vectors, withBaseline(changed));
  const VectorReport& now = vectorNamed(r, "fill_square.json");
  CHECK(now.status == Status::Failed);
  CHECK(now.baselineStage == Stage::DepthTest);
  CHECK_FALSE(r.passed());
  CHECK(r.changedStages() == 1);
  std::ostringstream line;
  printVectorLine(line, now);
  CHECK_THAT(line.str(),
             Catch::Contains("FAIL  fill_square.json (baseline expects depth test, now coverage)"));
  std::ostringstream summary;
  printSummary(summary, r);
  CHECK_THAT(summary.str(), Catch::Contains("(1 at another stage than the baseline's)"));
  CHECK_THAT(toJson(r), Catch::Contains("\"baseline_stage\": \"depth test\""));
  CHECK_THAT(toJunit(r), Catch::Contains("(baseline expects depth test, now coverage)"));
}

TEST_CASE("a baseline file: NAME,STAGE lines, comments, and the errors", "[baseline]") {
  const Baseline b = readBaseline(written("good",
                                          "# a comment\n\n  kit/slivers_3.json,coverage  \n"
                                          "odd, name.json , depth test\r\n"));
  CHECK(b.size() == 2);
  CHECK(b.at("kit/slivers_3.json") == Stage::Coverage);
  CHECK(b.at("odd, name.json") == Stage::DepthTest);  // the name ends at the last comma

  CHECK_THROWS_WITH(readBaseline(written("names", "# old\nfill_square.json\n")),
                    Catch::Contains("recode-baseline-test-names:2: \"fill_square.json\" has no "
                                    "stage: expected NAME,STAGE (e.g. "
                                    "kit/slivers_3.json,coverage)"));
  CHECK_THROWS_WITH(readBaseline(written("stage", "a.json,rasterisation\n")),
                    Catch::Contains(":1: unknown stage \"rasterisation\" (stages: validation, "
                                    "coverage,"));
  CHECK_THROWS_WITH(readBaseline(written("twice", "a.json,coverage\na.json,clear\n")),
                    Catch::Contains(":2: \"a.json\" is listed twice"));
  CHECK_THROWS_WITH(readBaseline(fs::temp_directory_path() / "recode-no-such-baseline"),
                    Catch::EndsWith("recode-no-such-baseline: cannot be read"));
}
