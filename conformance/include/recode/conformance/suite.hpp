#pragma once
// The conformance suite run on one back end: golden vectors (files) or random streams (the
// kit's families without their filter), sharded for CI, each vector run, compared, its bad
// pixels explained (diagnosis.hpp), failures held to a baseline of expected ones, a vector whose
// two runs differ marked nondeterministic, and the whole run's failures matched against the
// kit's wrong readings to name what the back end behaves like.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "recode/conformance/backend.hpp"
#include "recode/conformance/diagnosis.hpp"
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
// seed gives the same streams.
[[nodiscard]] std::vector<SuiteVector> randomVectors(int count, std::uint64_t seed);

// Shard `index` of `count` (0-based): every count-th vector from the index-th on, so that shards
// stay balanced whatever the order. Throws std::invalid_argument unless 0 <= index < count.
[[nodiscard]] std::vector<SuiteVector> shardOf(const std::vector<SuiteVector>& all, int index,
                                               int count);

// A baseline: names of vectors expected to fail, one per line; blank lines and lines starting
// with '#' are ignored. Throws std::runtime_error naming the file when it cannot be read.
[[nodiscard]] std::set<std::string> readBaseline(const std::filesystem::path& file);

enum class Status {
  Passed,
  Failed,
  ExpectedFailure,   // failed, and listed in the baseline
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
  std::optional<Requirement> requirement;   // for failing vectors
  double seconds = 0.0;                     // the back end's time on the vector
};

struct SuiteOptions {
  // Bad pixels of a failing vector explained with their history; 0 skips the explanations and
  // the wrong readings' answers they consult (the stage then comes from the history alone).
  std::size_t explainLimit = 64;
  bool classify = true;  // say for each vector whether the graphics APIs require its answer
  int repeat = 1;        // runs of every vector (a failing one is always run twice)
  std::set<std::string> baseline;
  bool stopAtFirstFailure = false;  // --random: stop at the first failing stream
  bool nameReadings = true;         // match the failures against the kit's wrong readings
};

struct SuiteReport {
  std::string backend;
  std::vector<VectorReport> vectors;
  // Wrong readings whose answers equal the back end's on every vector run (empty when all
  // passed or when none matches).
  std::vector<kit::Variant> behavesLike;
  std::string error;  // a BackendError that ended the run (its vector is the last one)
  [[nodiscard]] int count(Status s) const;
  [[nodiscard]] bool passed() const;  // no error and no status that fails the run
};

// Runs the suite; `onVector` (optional) sees each vector's report as soon as it is ready. A
// BackendError ends the run: it is kept in `error` and the report so far returned.
[[nodiscard]] SuiteReport runSuite(Backend& backend, const std::vector<SuiteVector>& vectors,
                                   const SuiteOptions& options,
                                   const std::function<void(const VectorReport&)>& onVector = {});

}  // namespace recode::conformance
