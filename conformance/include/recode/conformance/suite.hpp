#pragma once
// The conformance suite run on one back end: golden vectors (files) or random streams (the
// kit's families without their filter), sharded for CI, each vector run, compared, its bad
// pixels explained (diagnosis.hpp), failures held to a baseline of expected ones (each with the
// stage it fails at), a vector whose two runs differ marked nondeterministic, and the whole
// run's failures matched against the kit's wrong readings to name what the back end behaves
// like.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "recode/conformance/api_verdict.hpp"
#include "recode/conformance/backend.hpp"
#include "recode/conformance/diagnosis.hpp"
#include "recode/conformance/fingerprint.hpp"
#include "recode/raster/golden.hpp"

namespace recode::conformance {

struct SuiteVector {
  std::string name;  // the file relative to its directory, or "random-<seed>-<index>"
  raster::GoldenVector golden;
};

// Every *.json under `dir`, recursively, sorted by path; names relative to `dir`. Throws
// std::runtime_error for a missing or empty directory and raster::FormatError for a bad file.
[[nodiscard]] std::vector<SuiteVector> goldenVectors(const std::filesystem::path& dir);

// `count` random streams from seed `seed`: the kit's families in turn, each candidate drawn as
// the kit draws it but kept whatever it catches, expected buffers from the reference. The same
// seed gives the same streams. With `family`, every stream is of that family
// (kit::randomKitStream).
[[nodiscard]] std::vector<SuiteVector> randomVectors(int count, std::uint64_t seed,
                                                     std::string_view family = {});

// Shard `index` of `count` (0-based): every count-th vector from the index-th on, so that shards
// stay balanced whatever the order. Throws std::invalid_argument unless 0 <= index < count.
[[nodiscard]] std::vector<SuiteVector> shardOf(const std::vector<SuiteVector>& all, int index,
                                               int count);

// A baseline: the vectors expected to fail, each with the stage it fails at (as a CI baseline
// records each expected failure's status): a vector that fails at another stage is not
// expected.
using Baseline = std::map<std::string, Stage>;

// Reads a baseline file: one `NAME,STAGE` a line (the name as the report gives it, the stage as
// toString(Stage) spells it: `kit/slivers_3.json,coverage`; the name ends at the last comma);
// blank lines and lines starting with '#' are ignored. Throws std::runtime_error naming the
// file (and the line: "FILE:LINE: ...") when it cannot be read, a line has no stage or an
// unknown one, or a name is listed twice.
[[nodiscard]] Baseline readBaseline(const std::filesystem::path& file);

enum class Status {
  Passed,
  Failed,            // failed, and not listed in the baseline or listed with another stage
  ExpectedFailure,   // failed at the stage the baseline lists it with
  UnexpectedPass,    // passed, but listed in the baseline
  Nondeterministic,  // two runs of the vector gave different answers
};
[[nodiscard]] std::string_view toString(Status s);  // "pass", "FAIL", ...
// Whether the status fails the run: Failed, UnexpectedPass, Nondeterministic.
[[nodiscard]] bool failsRun(Status s);

struct VectorReport {
  std::string name;
  std::string description;
  Status status = Status::Passed;
  int width = 0, height = 0;
  std::string refused;  // the back end refused the stream
  long long badPixelCount = 0, depthPixels = 0, stencilPixels = 0;
  std::vector<BadPixel> badPixels;          // all of them, scan order
  std::vector<PixelExplanation> explained;  // the first explainLimit of them
  std::optional<Stage> stage;               // where a failing answer first departs
  std::optional<Requirement> requirement;   // whether the APIs fix each buffer (classify)
  std::optional<ApiTally> api;              // failing vectors' bad pixels against the APIs
  std::vector<ApiVerdict> apiVerdicts;      // the explained pixels' verdicts, in their order
  std::optional<Stage> baselineStage;       // the stage the baseline lists it with, if it does
  double seconds = 0.0;                     // the back end's time on the vector
};

struct SuiteOptions {
  // Bad pixels of a failing vector explained with their history; 0 skips the explanations and
  // the wrong readings' answers they consult (the stage then comes from the history alone).
  std::size_t explainLimit = 64;
  // Judge each vector and bad pixel against what the graphics APIs allow, and fingerprint the
  // freedoms the back end takes.
  bool classify = true;
  int repeat = 1;                   // runs of every vector (a failing one is always run twice)
  Baseline baseline;                // the expected failures
  bool stopAtFirstFailure = false;  // stop at the first failing vector (random streams)
  bool nameReadings = true;         // match the failures against the kit's wrong readings
};

struct SuiteReport {
  std::string backend;
  std::vector<VectorReport> vectors;
  // Wrong readings whose answers equal the back end's on every vector run (empty when all
  // passed or when none matches).
  std::vector<kit::Variant> behavesLike;
  // Which of the APIs' freedoms the back end takes (SuiteOptions::classify), from every vector
  // it answered.
  std::vector<FingerprintTrait> fingerprint;
  std::string error;  // a BackendError that ended the run, prefixed with its vector's name
  std::optional<BackendFailure> errorKind;  // how the back end broke, with `error`
  std::string errorVector;  // the vector it broke on; empty when it broke before any vector
  [[nodiscard]] int count(Status s) const;
  [[nodiscard]] bool passed() const;  // no error and no status that fails the run
  // Failed vectors that the baseline lists with another stage.
  [[nodiscard]] int changedStages() const;
};

// Runs the suite; `onVector` (optional) sees each vector's report as soon as it is ready. A
// BackendError ends the run: it is kept in `error` and the report so far returned. When the run
// names a reading the back end behaves like, that reading decides the failing vectors' stages
// and their statuses against the baseline are decided again: a status `onVector` saw may
// change (the report returned is final).
[[nodiscard]] SuiteReport runSuite(Backend& backend, const std::vector<SuiteVector>& vectors,
                                   const SuiteOptions& options,
                                   const std::function<void(const VectorReport&)>& onVector = {});

// The baseline of a finished run, in readBaseline's format: every vector that failed (expected
// or not) with its stage, under a comment naming the back end; a nondeterministic vector is
// left out (no baseline makes it pass).
[[nodiscard]] std::string toBaseline(const SuiteReport& report);

}  // namespace recode::conformance
