// `recode verify`'s verdict line, its JSON "passed" and its exit status come from one function
// (verifyRunPassed): a run whose modes broke a promise must not print VERIFIED.

#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "verify/verify_report.hpp"

using namespace recode;

namespace {

std::string report(const app::VerifyRun& run) {
  std::ostringstream out;
  app::printVerifyReport(out, run, false);
  return out.str();
}

app::VerifyRun runWithModes() {
  app::VerifyRun run;
  run.source = "post.json";
  run.modes.emplace();
  run.modes->pairs = 1;
  run.modes->truth = 1;
  return run;
}

}  // namespace

TEST_CASE("verify: modes that keep their promises are VERIFIED, exit 0") {
  const app::VerifyRun run = runWithModes();
  CHECK(app::verifyRunPassed(run));
  CHECK(report(run).find("verdict: VERIFIED") != std::string::npos);
  CHECK(app::verifyRunToJson(run)["passed"] == true);
}

TEST_CASE("verify: a broken mode promise fails the verdict line, the JSON and the exit status") {
  for (int broken = 0; broken < 4; ++broken) {
    app::VerifyRun run = runWithModes();
    verify::ModeCounts& m = *run.modes;
    (broken == 0   ? m.conservative.missed
     : broken == 1 ? m.conservativeBelowReference
     : broken == 2 ? m.conservativeExtrasBeyondBound
                   : m.adaptive.missed) = 1;
    INFO("promise " << broken);
    CHECK_FALSE(app::verifyRunPassed(run));
    const std::string text = report(run);
    CHECK(text.find("verdict: VERIFIED") == std::string::npos);
    CHECK(text.find("verdict: FAILED (modes broke their promises") != std::string::npos);
    CHECK(app::verifyRunToJson(run)["passed"] == false);
  }
}
