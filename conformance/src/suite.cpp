#include "recode/conformance/suite.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <span>
#include <stdexcept>

#include "recode/io/printable.hpp"
#include "recode/kit/generator.hpp"

namespace recode::conformance {

namespace fs = std::filesystem;

std::vector<SuiteVector> goldenVectors(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw std::runtime_error(dir.string() + ": not a directory");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw std::runtime_error(dir.string() + ": no golden vectors (*.json)");
  std::vector<SuiteVector> out;
  for (const fs::path& f : files)
    out.push_back({fs::relative(f, dir).generic_string(), raster::readGolden(f)});
  return out;
}

std::vector<SuiteVector> randomVectors(int count, std::uint64_t seed, std::string_view family) {
  if (count < 1)
    throw std::invalid_argument("random streams: expected at least 1, got " +
                                std::to_string(count));
  std::vector<SuiteVector> out;
  for (int i = 0; i < count; ++i) {
    kit::KitVector v = kit::randomKitStream(seed, i, family);
    out.push_back({std::move(v.name), std::move(v.golden)});
  }
  return out;
}

std::vector<SuiteVector> shardOf(const std::vector<SuiteVector>& all, int index, int count) {
  if (count < 1 || index < 0 || index >= count) {
    throw std::invalid_argument("shard " + std::to_string(index) + " of " + std::to_string(count) +
                                ": expected 0 <= index < count");
  }
  std::vector<SuiteVector> out;
  for (std::size_t i = static_cast<std::size_t>(index); i < all.size();
       i += static_cast<std::size_t>(count))
    out.push_back(all[i]);
  return out;
}

namespace {

std::string stageList() {
  std::string list;
  for (const StageInfo& s : allStages())
    list += (list.empty() ? "" : ", ") + std::string(s.name);
  return list;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

}  // namespace

Baseline readBaseline(const fs::path& file) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error(file.string() + ": cannot be read");
  Baseline baseline;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = trimmed(line);
    if (text.empty() || text.front() == '#')
      continue;
    const std::string where = file.string() + ":" + std::to_string(number) + ": ";
    const auto comma = text.rfind(',');
    if (comma == std::string::npos) {
      throw std::runtime_error(where + "\"" + io::printable(text) +
                               "\" has no stage: expected NAME,STAGE (e.g. "
                               "kit/slivers_3.json,coverage), the stage one of " +
                               stageList());
    }
    const std::string name = trimmed(text.substr(0, comma));
    const std::string stageText = trimmed(text.substr(comma + 1));
    const std::span<const StageInfo> stages = allStages();
    const auto stage = std::find_if(stages.begin(), stages.end(),
                                    [&](const StageInfo& s) { return s.name == stageText; });
    if (name.empty())
      throw std::runtime_error(where + "no vector name before the comma: expected NAME,STAGE");
    if (stage == stages.end()) {
      throw std::runtime_error(where + "unknown stage \"" + io::printable(stageText) +
                               "\" (stages: " + stageList() + ")");
    }
    if (!baseline.emplace(name, stage->stage).second)
      throw std::runtime_error(where + "\"" + io::printable(name) + "\" is listed twice");
  }
  return baseline;
}

std::string toBaseline(const SuiteReport& report) {
  std::string text =
      "# Expected failures of " + io::printable(report.backend) + ", one NAME,STAGE a line.\n";
  for (const VectorReport& v : report.vectors) {
    if ((v.status == Status::Failed || v.status == Status::ExpectedFailure) && v.stage)
      text += v.name + "," + std::string(toString(*v.stage)) + "\n";
  }
  return text;
}

std::string_view toString(Status s) {
  switch (s) {
    case Status::Passed:
      return "pass";
    case Status::Failed:
      return "FAIL";
    case Status::ExpectedFailure:
      return "expected failure";
    case Status::UnexpectedPass:
      return "UNEXPECTED PASS";
    case Status::Nondeterministic:
      return "NONDETERMINISTIC";
  }
  return "?";
}

bool failsRun(Status s) {
  return s == Status::Failed || s == Status::UnexpectedPass || s == Status::Nondeterministic;
}

int SuiteReport::count(Status s) const {
  return static_cast<int>(std::count_if(vectors.begin(), vectors.end(),
                                        [s](const VectorReport& v) { return v.status == s; }));
}

int SuiteReport::changedStages() const {
  return static_cast<int>(std::count_if(vectors.begin(), vectors.end(), [](const VectorReport& v) {
    return v.status == Status::Failed && v.baselineStage.has_value();
  }));
}

bool SuiteReport::passed() const {
  return error.empty() && std::none_of(vectors.begin(), vectors.end(),
                                       [](const VectorReport& v) { return failsRun(v.status); });
}

namespace {

// A vector's status from its runs and the baseline: a failure is expected only at the stage the
// baseline lists it with.
Status statusOf(bool fails, bool differentRuns, const std::optional<Stage>& stage,
                const std::optional<Stage>& expected) {
  if (differentRuns)
    return Status::Nondeterministic;
  if (fails)
    return expected && stage == expected ? Status::ExpectedFailure : Status::Failed;
  return expected ? Status::UnexpectedPass : Status::Passed;
}

Answer expectedOf(const raster::GoldenVector& g) {
  return {g.depth, g.stencil, {}};
}

// Counts and explains a failing answer.
void explainFailure(const SuiteVector& v, const Answer& expected, const Answer& got,
                    const SuiteOptions& options, const AllowedFrame* allowed, VectorReport& r) {
  const raster::CommandStream& stream = v.golden.stream;
  r.refused = got.refused;
  if (got.wasRefused()) {
    r.stage = Stage::Validation;
    return;
  }
  r.badPixels = badPixels(stream, expected, got, SIZE_MAX, &r.badPixelCount);
  for (const BadPixel& p : r.badPixels) {
    r.depthPixels += p.depthDiffers() ? 1 : 0;
    r.stencilPixels += p.stencilDiffers() ? 1 : 0;
  }
  std::vector<ReadingAnswer> readings =
      options.explainLimit > 0 ? readingAnswers(stream) : std::vector<ReadingAnswer>{};
  // A reading that gives the back end's whole answer is the likeliest explanation of each of its
  // pixels: consulted first.
  std::stable_partition(readings.begin(), readings.end(),
                        [&](const ReadingAnswer& a) { return a.answer == got; });
  const std::size_t n = std::min(options.explainLimit, r.badPixels.size());
  for (std::size_t i = 0; i < n; ++i)
    r.explained.push_back(explainPixel(stream, r.badPixels[i], readings));
  r.stage = r.explained.empty() ? failingStage(stream, expected, got, readings)
                                : r.explained.front().stage;
  if (allowed) {
    r.api = tallyByApis(*allowed, r.badPixels);
    for (const PixelExplanation& e : r.explained)
      r.apiVerdicts.push_back(judgeByApis(stream, e.pixel));
  }
}

// The wrong readings whose answers equal the back end's on every vector: eliminated on the
// failing vectors first (few survive the first one), then confirmed on the passing ones.
std::vector<kit::Variant> matchingReadings(const std::vector<SuiteVector>& run,
                                           const std::vector<Answer>& answers,
                                           const std::vector<bool>& failed) {
  std::vector<kit::Variant> candidates;
  for (const kit::VariantInfo& v : kit::wrongVariants())
    candidates.push_back(v.variant);
  for (const bool failingPass : {true, false}) {
    for (std::size_t i = 0; i < run.size() && !candidates.empty(); ++i) {
      if (failed[i] != failingPass)
        continue;
      std::erase_if(candidates, [&](kit::Variant v) {
        ModelBackend model(v);
        return !(model.run(run[i].golden.stream) == answers[i]);
      });
    }
  }
  return candidates;
}

}  // namespace

SuiteReport runSuite(Backend& backend, const std::vector<SuiteVector>& vectors,
                     const SuiteOptions& options,
                     const std::function<void(const VectorReport&)>& onVector) {
  SuiteReport report;
  report.backend = backend.name();
  std::vector<SuiteVector> run;
  std::vector<Answer> answers;
  std::vector<bool> failed;
  FingerprintBuilder fingerprint;
  for (const SuiteVector& v : vectors) {
    VectorReport r;
    r.name = v.name;
    r.description = v.golden.description;
    r.width = v.golden.stream.width;
    r.height = v.golden.stream.height;
    const Answer expected = expectedOf(v.golden);
    Answer got;
    bool differentRuns = false;
    try {
      const auto start = std::chrono::steady_clock::now();
      got = backend.run(v.golden.stream);
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const int runs = std::max(options.repeat, got == expected ? 1 : 2);
      for (int k = 1; k < runs && !differentRuns; ++k)
        differentRuns = !(backend.run(v.golden.stream) == got);
    } catch (const BackendError& e) {
      report.error = v.name + ": " + e.what();
      report.errorKind = e.kind();
      report.errorVector = v.name;
      break;
    }
    const bool fails = !(got == expected);
    if (const auto listed = options.baseline.find(v.name); listed != options.baseline.end())
      r.baselineStage = listed->second;
    std::optional<AllowedFrame> allowed;
    if (options.classify) {
      allowed = allowedByApis(v.golden.stream);
      r.requirement = requirementOf(*allowed);
      fingerprint.add(v.name, v.golden.stream, expected, got);
    }
    if (fails)
      explainFailure(v, expected, got, options, allowed ? &*allowed : nullptr, r);
    r.status = statusOf(fails, differentRuns, r.stage, r.baselineStage);
    if (onVector)
      onVector(r);
    report.vectors.push_back(std::move(r));
    if (!differentRuns) {
      run.push_back(v);
      answers.push_back(std::move(got));
      failed.push_back(fails);
    }
    if (fails && options.stopAtFirstFailure)
      break;
  }
  if (options.classify)
    report.fingerprint = fingerprint.traits();
  const bool anyFailed = std::find(failed.begin(), failed.end(), true) != failed.end();
  if (options.nameReadings && anyFailed)
    report.behavesLike = matchingReadings(run, answers, failed);
  // The reading the back end behaves like gives its values at every pixel of every vector: it,
  // rather than whichever reading a pixel happens to match first, says where each departs.
  if (!report.behavesLike.empty()) {
    const kit::Variant named = report.behavesLike.front();
    for (VectorReport& r : report.vectors) {
      if (!r.stage || r.status == Status::Nondeterministic)
        continue;
      r.stage = stageOf(named);
      for (PixelExplanation& e : r.explained)
        attributeToReading(e, named);
      r.status = statusOf(true, false, r.stage, r.baselineStage);
    }
  }
  return report;
}

}  // namespace recode::conformance
