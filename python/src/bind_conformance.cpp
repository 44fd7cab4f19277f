// recode.conformance: the conformance suite (recode/conformance/*.hpp, docs/conformance.md) for a
// back end written in Python. The golden vectors as objects, check() of one answer with the
// facts `recode conform` gives for a vector, and a whole run over a Python callable with the
// reports the program writes (text, JSON, JUnit, HTML, a baseline). The C++ work runs without
// the GIL; the callable is called with it (PythonBackend).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "recode/conformance/api_verdict.hpp"
#include "recode/conformance/backend.hpp"
#include "recode/conformance/diagnosis.hpp"
#include "recode/conformance/fingerprint.hpp"
#include "recode/conformance/report.hpp"
#include "recode/conformance/suite.hpp"
#include "recode/kit/variants.hpp"
#include "recode/raster/golden.hpp"

namespace recode::python {

namespace {

namespace conf = recode::conformance;
namespace fs = std::filesystem;

// The directories searched for the golden vectors when none is given, in order (after the
// environment variable RECODE_GOLDEN_DIR): the source tree's data/golden, then where
// `cmake --install` puts them (python/CMakeLists.txt compiles both in).
constexpr std::array<const char*, 2> kGoldenDirs = {RECODE_PYTHON_GOLDEN_DIR,
                                                    RECODE_PYTHON_INSTALLED_GOLDEN_DIR};

// The Python exception a back end raises to refuse a stream (section 2): recode.conformance.
// Refused. Its C++ side is never thrown; the type is looked up by PythonBackend.
struct RefusedTag : std::runtime_error {
  using std::runtime_error::runtime_error;
};
py::handle refusedType;

std::string pathText(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

fs::path defaultGoldenDir() {
  py::object env = py::module_::import("os").attr("environ").attr("get")("RECODE_GOLDEN_DIR");
  if (!env.is_none())
    return env.cast<std::string>();
  for (const char* dir : kGoldenDirs) {
    if (*dir != '\0' && fs::is_directory(dir))
      return dir;
  }
  std::string searched;
  for (const char* dir : kGoldenDirs)
    searched += *dir != '\0' ? std::string(searched.empty() ? "" : ", ") + dir : "";
  fileNotFound("no golden vectors found (searched " + searched +
               "): pass the directory (the source tree's data/golden, or share/recode/golden "
               "under the prefix RECODE was installed to) or set RECODE_GOLDEN_DIR");
}

fs::path goldenDirOf(const std::optional<py::object>& directory) {
  return directory && !directory->is_none() ? fs::path(pathText(*directory)) : defaultGoldenDir();
}

// conf::goldenVectors with a missing directory as FileNotFoundError (its message the C++ one);
// a malformed file is recode.conformance.FormatError.
std::vector<conf::SuiteVector> readVectors(const fs::path& dir) {
  if (!fs::is_directory(dir)) {
    try {
      (void)conf::goldenVectors(dir);
    } catch (const std::runtime_error& e) {
      fileNotFound(e.what());
    }
  }
  return conf::goldenVectors(dir);
}

py::object commandsOf(const raster::CommandStream& stream) {
  return py::module_::import("json").attr("loads")(raster::commandStreamToJson(stream))["commands"];
}

// One buffer of an answer: a (height, width) array, row 0 the bottom row, or the same values
// flat, of integers in 0..`max`. Throws py::type_error / py::value_error naming `what`.
template <class T>
std::vector<T> bufferFrom(const py::handle& object, const std::string& what, int width, int height,
                          std::uint32_t max) {
  const py::array raw = integerArray(object, what, "integers");
  const auto pixels = static_cast<py::ssize_t>(width) * height;
  const std::vector<py::ssize_t> grid{height, width};
  const bool flat = raw.ndim() == 1 && raw.shape(0) == pixels;
  if (!flat && !(raw.ndim() == 2 && raw.shape(0) == height && raw.shape(1) == width))
    throw py::value_error(what + ": expected shape " + shapeText(grid) +
                          " (height, width; row 0 the bottom row) or " +
                          shapeText(std::vector<py::ssize_t>{pixels}) + ", got " + shapeText(raw));
  const std::vector<py::ssize_t> shape = flat ? std::vector<py::ssize_t>{pixels} : grid;
  const std::vector<std::uint64_t> values = integersBelow(
      raw, std::uint64_t{max} + 1, [&](std::size_t i, const std::string& value, bool) {
        throw py::value_error(what + "[" + indexText(shape, i) + "]: expected an integer in 0.." +
                              std::to_string(max) + ", got " + value);
      });
  std::vector<T> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    out[i] = static_cast<T>(values[i]);
  return out;
}

conf::Answer answerFrom(const py::handle& depth, const py::handle& stencil, int width, int height,
                        const std::string& prefix) {
  conf::Answer a;
  a.depth = bufferFrom<std::uint32_t>(depth, prefix + "depth", width, height, 16777215u);
  a.stencil = bufferFrom<std::uint8_t>(stencil, prefix + "stencil", width, height, 255u);
  return a;
}

// A Python callable backend(width, height, commands) -> (depth, stencil) as a back end of the
// suite. run() is called without the GIL (runSuite runs released) and takes it for the call. A
// recode.conformance.Refused raised by the callable is a refusal; an answer that is not two
// buffers of the frame's size and range is a BackendError (malformed), which ends the run as a
// protocol error ends `recode conform`'s; any other Python exception propagates out of run().
class PythonBackend final : public conf::Backend {
 public:
  PythonBackend(py::object callable, std::string name)
      : callable_(std::move(callable)), name_(std::move(name)) {}
  [[nodiscard]] std::string name() const override { return name_; }

  [[nodiscard]] conf::Answer run(const raster::CommandStream& stream) override {
    const py::gil_scoped_acquire gil;
    const std::string what = "request " + std::to_string(++requests_);
    py::object result;
    try {
      result = callable_(stream.width, stream.height, commandsOf(stream));
    } catch (py::error_already_set& e) {
      if (!e.matches(refusedType))
        throw;
      conf::Answer refused;
      refused.refused = py::str(e.value()).cast<std::string>();
      if (refused.refused.empty())
        refused.refused = "refused";
      return refused;
    }
    if (!py::isinstance<py::sequence>(result) || py::isinstance<py::str>(result) ||
        py::len(result) != 2) {
      throw conf::BackendError(conf::BackendFailure::Malformed,
                               what + ": the back end returned " +
                                   py::repr(result).cast<std::string>().substr(0, 200) +
                                   ", expected (depth, stencil)");
    }
    const py::sequence pair = result.cast<py::sequence>();
    try {
      return answerFrom(pair[0], pair[1], stream.width, stream.height, "answer.");
    } catch (const py::builtin_exception& e) {
      throw conf::BackendError(conf::BackendFailure::Malformed, what + ": " + e.what());
    }
  }

 private:
  py::object callable_;
  std::string name_;
  long long requests_ = 0;
};

// The same answer to every stream: check()'s one answer, run as a suite of one vector.
class FixedBackend final : public conf::Backend {
 public:
  explicit FixedBackend(conf::Answer answer) : answer_(std::move(answer)) {}
  [[nodiscard]] std::string name() const override { return "check"; }
  [[nodiscard]] conf::Answer run(const raster::CommandStream&) override { return answer_; }

 private:
  conf::Answer answer_;
};

std::string readingName(kit::Variant v) {
  return std::string(kit::variantName(v));
}

std::vector<std::string> readingNames(const std::vector<kit::Variant>& readings) {
  std::vector<std::string> out;
  for (const kit::Variant v : readings)
    out.push_back(readingName(v));
  return out;
}

std::vector<std::string> freedomNames(conf::FreedomSet set) {
  return conf::namesOf(set);
}

// None for "" (the report's way of saying "none"), else the text.
std::optional<std::string> noneIfEmpty(const std::string& s) {
  return s.empty() ? std::nullopt : std::optional<std::string>(s);
}

std::optional<std::string> stageName(const std::optional<conf::Stage>& s) {
  return s ? std::optional<std::string>(conf::toString(*s)) : std::nullopt;
}

// One explained bad pixel, with its verdict against the APIs when the run judged it.
struct Explanation {
  conf::PixelExplanation e;
  std::optional<conf::ApiVerdict> verdict;
};

// One vector's result (a check, or a vector of a run): a vector of the run's report, which it
// shares with the Report and the run's other results (no copies of the bad pixels).
struct VectorResult {
  std::shared_ptr<const conf::SuiteReport> run;
  std::size_t index = 0;

  [[nodiscard]] const conf::VectorReport& report() const { return run->vectors[index]; }
  [[nodiscard]] std::string text(std::size_t explain) const {
    std::ostringstream out;
    conf::printVector(out, report(), explain);
    return out.str();
  }
  // The vector's entry of `recode conform --json`'s "results".
  [[nodiscard]] py::object json() const {
    conf::SuiteReport one;
    one.vectors.push_back(report());
    return py::module_::import("json").attr("loads")(conf::toJson(one))["results"][py::int_(0)];
  }
};

std::vector<VectorResult> resultsOf(const std::shared_ptr<const conf::SuiteReport>& run) {
  std::vector<VectorResult> out;
  for (std::size_t i = 0; i < run->vectors.size(); ++i)
    out.push_back({run, i});
  return out;
}

// A whole run and what it was run on, for the text report's first line.
struct Report {
  std::shared_ptr<const conf::SuiteReport> run;
  std::string source;  // "307 golden vectors under DIR"

  [[nodiscard]] const conf::SuiteReport& report() const { return *run; }

  // What `recode conform` prints: the first line, a line per vector, the failures explained,
  // the summary. The vectors' lines give their final statuses (the program prints each as it
  // finishes, before the run names a reading; without a baseline they are the same).
  [[nodiscard]] std::string text(std::size_t explain) const {
    std::ostringstream out;
    const conf::SuiteReport& report = *run;
    out << "recode conform: back end " << report.backend << ", " << source << '\n';
    for (const conf::VectorReport& v : report.vectors)
      conf::printVectorLine(out, v);
    if (std::any_of(report.vectors.begin(), report.vectors.end(), conf::hasDetails)) {
      out << "\nFailures explained:\n";
      for (const conf::VectorReport& v : report.vectors) {
        if (conf::hasDetails(v))
          conf::printVector(out, v, explain);
      }
      out << '\n';
    }
    conf::printSummary(out, report);
    return out.str();
  }
};

conf::Stage stageFrom(const std::string& name, const std::string& what) {
  std::string stages;
  for (const conf::StageInfo& s : conf::allStages()) {
    if (s.name == name)
      return s.stage;
    stages += (stages.empty() ? "" : ", ") + std::string(s.name);
  }
  throw py::value_error(what + ": unknown stage '" + name + "' (stages: " + stages + ")");
}

// A baseline: a file in readBaseline's format, or a mapping of vector names to stages.
conf::Baseline baselineFrom(const py::object& baseline) {
  if (baseline.is_none())
    return {};
  if (py::isinstance<py::dict>(baseline)) {
    conf::Baseline out;
    for (const auto& [name, stage] : baseline.cast<py::dict>()) {
      const std::string key = py::str(name).cast<std::string>();
      out.emplace(key, stageFrom(py::str(stage).cast<std::string>(), "baseline[" + key + "]"));
    }
    return out;
  }
  const std::string file = pathText(baseline);
  if (!fs::exists(file))
    fileNotFound(file + ": cannot be read");
  return conf::readBaseline(file);
}

conf::SuiteOptions optionsOf(std::size_t explain, int repeat, const py::object& baseline) {
  if (repeat < 1 || repeat > 100)
    throw py::value_error("repeat: " + std::to_string(repeat) + " is outside 1..100");
  conf::SuiteOptions o;
  o.explainLimit = explain;
  o.repeat = repeat;
  o.baseline = baselineFrom(baseline);
  return o;
}

// A record of VectorResult.bad_pixels: conf::BadPixel's fields under their Python names,
// packed (18 bytes), the array's dtype since the module first had it.
#pragma pack(push, 1)
struct BadPixelRecord {
  std::int32_t x, y;
  std::uint32_t expected_depth, got_depth;
  std::uint8_t expected_stencil, got_stencil;
};
#pragma pack(pop)
static_assert(sizeof(BadPixelRecord) == 18, "bad_pixels records are packed");

py::array_t<BadPixelRecord> badPixelArray(const std::vector<conf::BadPixel>& bad) {
  py::array_t<BadPixelRecord> out(static_cast<py::ssize_t>(bad.size()));
  BadPixelRecord* records = out.mutable_data();
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const conf::BadPixel& p = bad[i];
    records[i] = {p.x, p.y, p.expectedDepth, p.gotDepth, p.expectedStencil, p.gotStencil};
  }
  return out;
}

std::string repr(const VectorResult& r) {
  std::string s = "<recode.conformance.VectorResult " + r.report().name + ": " +
                  std::string(conf::toString(r.report().status));
  if (r.report().stage) {
    s += r.report().refused.empty()
             ? ", " + std::to_string(r.report().badPixelCount) + " bad pixels"
             : ", refused";
    s += ", stage " + std::string(conf::toString(*r.report().stage));
  }
  return s + ">";
}

conf::SuiteVector vectorFromFile(const py::object& path) {
  const fs::path file = pathText(path);
  if (!fs::exists(file))
    fileNotFound(file.string() + ": no such file");
  return conf::SuiteVector{file.filename().string(), raster::readGolden(file)};
}

// Per buffer, whether the graphics APIs fix every pixel of the vector or only the contract.
py::object requirementOf(const VectorResult& r) {
  if (!r.report().requirement)
    return py::none();
  const auto by = [](const conf::BufferRequirement& b) {
    return b.byGraphicsApis ? "graphics APIs" : "contract only";
  };
  py::dict d;
  d["depth"] = by(r.report().requirement->depth);
  d["stencil"] = by(r.report().requirement->stencil);
  return d;
}

// A failing vector's bad pixels against the graphics APIs, as the JSON's "api".
py::object apiOf(const VectorResult& r) {
  if (!r.report().api)
    return py::none();
  py::dict d;
  d["forbidden_pixels"] = r.report().api->forbidden;
  d["freedom_pixels"] = r.report().api->withinFreedom;
  d["freedoms"] = freedomNames(r.report().api->freedoms);
  return d;
}

std::vector<Explanation> explanationsOf(const VectorResult& r) {
  const conf::VectorReport& report = r.report();
  std::vector<Explanation> out;
  for (std::size_t i = 0; i < report.explained.size(); ++i) {
    out.push_back({report.explained[i], i < report.apiVerdicts.size()
                                            ? std::optional<conf::ApiVerdict>(report.apiVerdicts[i])
                                            : std::nullopt});
  }
  return out;
}

std::vector<VectorResult> failuresOf(const Report& r) {
  std::vector<VectorResult> out;
  for (VectorResult& v : resultsOf(r.run)) {
    if (conf::failsRun(v.report().status))
      out.push_back(std::move(v));
  }
  return out;
}

py::dict countsOf(const Report& r) {
  py::dict d;
  d["passed"] = r.report().count(conf::Status::Passed);
  d["failed"] = r.report().count(conf::Status::Failed);
  d["expected_failures"] = r.report().count(conf::Status::ExpectedFailure);
  d["unexpected_passes"] = r.report().count(conf::Status::UnexpectedPass);
  d["nondeterministic"] = r.report().count(conf::Status::Nondeterministic);
  return d;
}

std::string summaryOf(const Report& r) {
  std::ostringstream out;
  conf::printSummary(out, r.report());
  return out.str();
}

std::string reportJson(const Report& r, const py::kwargs& fields) {
  std::vector<std::pair<std::string, std::string>> extra;
  for (const auto& [key, value] : fields)
    extra.emplace_back(py::str(key).cast<std::string>(), py::str(value).cast<std::string>());
  return conf::toJson(r.report(), extra);
}

std::string reportRepr(const Report& r) {
  return "<recode.conformance.Report " + r.report().backend + ": " +
         std::to_string(r.report().vectors.size()) + " vectors, " +
         std::to_string(r.report().count(conf::Status::Passed)) + " passed, " +
         std::to_string(r.report().count(conf::Status::Failed)) + " failed" +
         (r.report().error.empty() ? "" : ", error") + ">";
}

// check(): one answer to `vector` (two buffers, or a refusal), run as a suite of that vector.
VectorResult checkAnswer(const conf::SuiteVector& vector, const py::object& depth,
                         const py::object& stencil, const std::optional<std::string>& refused,
                         std::size_t explain, const py::object& baselineStage) {
  conf::Answer answer;
  if (refused) {
    if (refused->empty())
      throw py::value_error("refused: expected the reason, got ''");
    answer.refused = *refused;
  } else {
    if (depth.is_none() || stencil.is_none())
      throw py::type_error("check: expected depth and stencil, or refused=REASON");
    answer =
        answerFrom(depth, stencil, vector.golden.stream.width, vector.golden.stream.height, "");
  }
  conf::SuiteOptions options;
  options.explainLimit = explain;
  if (!baselineStage.is_none())
    options.baseline.emplace(
        vector.name, stageFrom(py::str(baselineStage).cast<std::string>(), "baseline_stage"));
  FixedBackend backend(std::move(answer));
  const std::vector<conf::SuiteVector> one = {vector};
  conf::SuiteReport report;
  {
    const py::gil_scoped_release release;
    report = conf::runSuite(backend, one, options);
  }
  return VectorResult{std::make_shared<const conf::SuiteReport>(std::move(report)), 0};
}

// run()'s vectors: a directory (None: golden_dir()) or a list of Vector, and the words for the
// report's first line.
std::pair<std::vector<conf::SuiteVector>, std::string> vectorsToRun(const py::object& vectors) {
  std::vector<conf::SuiteVector> list;
  if (vectors.is_none() || py::isinstance<py::str>(vectors) || py::hasattr(vectors, "__fspath__")) {
    const fs::path dir =
        goldenDirOf(vectors.is_none() ? std::nullopt : std::optional<py::object>(vectors));
    list = readVectors(dir);
    std::string source = std::to_string(list.size()) + " golden vectors under " + dir.string();
    return {std::move(list), std::move(source)};
  }
  for (const py::handle v : vectors)
    list.push_back(v.cast<conf::SuiteVector>());
  std::string source = std::to_string(list.size()) + " golden vectors";
  return {std::move(list), std::move(source)};
}

// The back end's name in the reports: `name`, else the callable's __name__, else its type's.
std::string backendNameOf(const py::object& backend, const std::optional<std::string>& name) {
  if (name)
    return *name;
  if (py::hasattr(backend, "__name__"))
    return py::str(backend.attr("__name__")).cast<std::string>();
  return py::str(py::type::of(backend).attr("__name__")).cast<std::string>();
}

// run(): the suite on a Python callable, in this process.
Report runBackend(const py::object& backend, const py::object& vectors,
                  const std::optional<std::string>& name, std::size_t explain, int repeat,
                  const py::object& baseline) {
  if (!PyCallable_Check(backend.ptr()))
    throw py::type_error(
        "backend: expected a callable backend(width, height, commands) -> (depth, stencil), "
        "got " +
        py::str(py::type::of(backend)).cast<std::string>());
  auto [list, source] = vectorsToRun(vectors);
  const conf::SuiteOptions options = optionsOf(explain, repeat, baseline);
  PythonBackend python(backend, backendNameOf(backend, name));
  Report report;
  report.source = std::move(source);
  {
    const py::gil_scoped_release release;
    report.run = std::make_shared<const conf::SuiteReport>(conf::runSuite(python, list, options));
  }
  return report;
}

void bindVector(py::module_& m) {
  py::class_<conf::SuiteVector>(
      m, "Vector",
      "A golden vector: a command stream for a fresh width x height framebuffer and the depth "
      "and stencil buffers the contract gives.")
      .def_static("from_file", &vectorFromFile, py::arg("path"),
                  "Reads one golden file (recode-golden-1); its name is the file name.")
      .def_readonly("name", &conf::SuiteVector::name,
                    "The file relative to the directory it was read from, e.g. "
                    "'kit/slivers_3.json' (the name the reports use).")
      .def_property_readonly("description",
                             [](const conf::SuiteVector& v) { return v.golden.description; })
      .def_property_readonly("width",
                             [](const conf::SuiteVector& v) { return v.golden.stream.width; })
      .def_property_readonly("height",
                             [](const conf::SuiteVector& v) { return v.golden.stream.height; })
      .def_property_readonly(
          "commands", [](const conf::SuiteVector& v) { return commandsOf(v.golden.stream); },
          "The commands as the golden file has them (rasterization.md section 8): a new list "
          "of dicts on each access, e.g. {'op': 'draw', 'vertices_fixed': [[X, Y, z], ...], "
          "'indices': [...]}, vertices in 24.8 fixed point.")
      .def_property_readonly(
          "depth",
          [](const py::object& self) {
            const auto& v = self.cast<const conf::SuiteVector&>();
            return gridView(v.golden.depth, v.golden.stream.height, v.golden.stream.width, self);
          },
          "The expected depth buffer: read-only uint32 (height, width), row 0 the bottom row.")
      .def_property_readonly(
          "stencil",
          [](const py::object& self) {
            const auto& v = self.cast<const conf::SuiteVector&>();
            return gridView(v.golden.stencil, v.golden.stream.height, v.golden.stream.width, self);
          },
          "The expected stencil buffer: read-only uint8 (height, width), row 0 the bottom row.")
      .def(
          "to_json",
          [](const conf::SuiteVector& v) {
            return raster::goldenToJson(v.golden, raster::GoldenLayout::Rows);
          },
          "The vector as a golden file (recode-golden-1), one command and one row a line.")
      .def("__repr__", [](const conf::SuiteVector& v) {
        return "<recode.conformance.Vector " + v.name + ": " +
               std::to_string(v.golden.stream.width) + " x " +
               std::to_string(v.golden.stream.height) + ", " +
               std::to_string(v.golden.stream.commands.size()) + " commands>";
      });
}

void bindExplanation(py::module_& m) {
  py::class_<Explanation>(m, "Explanation",
                          "A bad pixel explained: where the back end's answer departs from the "
                          "contract there, why, the pixel's history and the APIs' verdict.")
      .def_property_readonly("x", [](const Explanation& x) { return x.e.pixel.x; })
      .def_property_readonly(
          "y", [](const Explanation& x) { return x.e.pixel.y; },
          "GL window coordinates: y = 0 is the bottom row.")
      .def_property_readonly("expected_depth",
                             [](const Explanation& x) { return x.e.pixel.expectedDepth; })
      .def_property_readonly("got_depth", [](const Explanation& x) { return x.e.pixel.gotDepth; })
      .def_property_readonly("expected_stencil",
                             [](const Explanation& x) { return x.e.pixel.expectedStencil; })
      .def_property_readonly("got_stencil",
                             [](const Explanation& x) { return x.e.pixel.gotStencil; })
      .def_property_readonly(
          "stage", [](const Explanation& x) { return std::string(conf::toString(x.e.stage)); })
      .def_property_readonly(
          "contract_section",
          [](const Explanation& x) { return std::string(conf::contractSection(x.e.stage)); })
      .def_property_readonly("why", [](const Explanation& x) { return x.e.why; })
      .def_property_readonly(
          "rule", [](const Explanation& x) { return std::string(x.e.rule); },
          "The stage rule that read the history, e.g. 'no trace of a fragment'.")
      .def_property_readonly(
          "reading",
          [](const Explanation& x) {
            return x.e.sameAsReading ? std::optional<std::string>(readingName(*x.e.sameAsReading))
                                     : std::nullopt;
          },
          "The kit's wrong reading that gives the back end's values here (e.g. "
          "'top_left_fill'), or None.")
      .def_property_readonly(
          "history", [](const Explanation& x) { return conf::describe(x.e.history); },
          "The contract's history of the pixel, as the report prints it.")
      .def_property_readonly(
          "api_allowed",
          [](const Explanation& x) {
            return x.verdict ? std::optional<bool>(x.verdict->allowed) : std::nullopt;
          },
          "Whether the graphics APIs allow the back end's values here (None when not judged).")
      .def_property_readonly(
          "api",
          [](const Explanation& x) {
            return x.verdict ? std::optional<std::string>(
                                   conf::describe(*x.verdict, x.e.pixel, x.e.stage))
                             : std::nullopt;
          },
          "The verdict against the APIs as the report words it: within which freedoms, or "
          "forbidden and by which clause.")
      .def_property_readonly("api_freedoms",
                             [](const Explanation& x) {
                               return x.verdict ? freedomNames(x.verdict->freedoms)
                                                : std::vector<std::string>{};
                             })
      .def_property_readonly(
          "api_clause",
          [](const Explanation& x) {
            return x.verdict && !x.verdict->allowed
                       ? std::optional<std::string>(
                             conf::apiClause(conf::forbiddenStage(*x.verdict, x.e.stage)))
                       : std::nullopt;
          },
          "For a forbidden pixel, the clause of the APIs it breaks; else None.")
      .def("__repr__", [](const Explanation& x) {
        return "<recode.conformance.Explanation pixel (" + std::to_string(x.e.pixel.x) + ", " +
               std::to_string(x.e.pixel.y) + "): " + std::string(conf::toString(x.e.stage)) + ">";
      });
}

void bindVectorResult(py::module_& m) {
  PYBIND11_NUMPY_DTYPE(BadPixelRecord, x, y, expected_depth, got_depth, expected_stencil,
                       got_stencil);
  py::class_<VectorResult>(
      m, "VectorResult",
      "One vector's result, with the facts `recode conform` gives for it; str() is its report.")
      .def_property_readonly("name", [](const VectorResult& r) { return r.report().name; })
      .def_property_readonly("description",
                             [](const VectorResult& r) { return r.report().description; })
      .def_property_readonly("width", [](const VectorResult& r) { return r.report().width; })
      .def_property_readonly("height", [](const VectorResult& r) { return r.report().height; })
      .def_property_readonly(
          "status",
          [](const VectorResult& r) { return std::string(conf::toString(r.report().status)); },
          "'pass', 'FAIL', 'expected failure', 'UNEXPECTED PASS' or 'NONDETERMINISTIC'.")
      .def_property_readonly(
          "passed", [](const VectorResult& r) { return r.report().status == conf::Status::Passed; })
      .def_property_readonly("refused",
                             [](const VectorResult& r) { return noneIfEmpty(r.report().refused); })
      .def_property_readonly("bad_pixel_count",
                             [](const VectorResult& r) { return r.report().badPixelCount; })
      .def_property_readonly("depth_pixel_count",
                             [](const VectorResult& r) { return r.report().depthPixels; })
      .def_property_readonly("stencil_pixel_count",
                             [](const VectorResult& r) { return r.report().stencilPixels; })
      .def_property_readonly(
          "bad_pixels", [](const VectorResult& r) { return badPixelArray(r.report().badPixels); },
          "Every bad pixel in scan order (bottom row first): a structured NumPy array with "
          "fields x, y (int32), expected_depth, got_depth (uint32), expected_stencil, "
          "got_stencil (uint8).")
      .def_property_readonly(
          "stage", [](const VectorResult& r) { return stageName(r.report().stage); },
          "Where a failing answer first departs ('coverage', 'depth value', ...), else None.")
      .def_property_readonly(
          "contract_section",
          [](const VectorResult& r) {
            return r.report().stage
                       ? std::optional<std::string>(conf::contractSection(*r.report().stage))
                       : std::nullopt;
          })
      .def_property_readonly(
          "required_by", &requirementOf,
          "Per buffer, whether the graphics APIs fix every pixel of the vector ('graphics "
          "APIs') or only this contract does ('contract only').")
      .def_property_readonly(
          "api", &apiOf,
          "A failing vector's bad pixels against the graphics APIs, as the JSON's 'api': "
          "forbidden_pixels, freedom_pixels, freedoms; None for a passing one.")
      .def_property_readonly("explained", &explanationsOf,
                             "The first `explain` bad pixels explained, as Explanation objects.")
      .def_property_readonly(
          "behaves_like", [](const VectorResult& r) { return readingNames(r.run->behavesLike); },
          "The kit's wrong readings the run names (whose answers equal the back end's on every "
          "vector of the run: for check(), on this vector), e.g. ['top_left_fill'].")
      .def_property_readonly(
          "baseline_stage",
          [](const VectorResult& r) { return stageName(r.report().baselineStage); })
      .def_property_readonly("seconds", [](const VectorResult& r) { return r.report().seconds; })
      .def("text", &VectorResult::text, py::arg("explain") = 4,
           "The vector's report as `recode conform --explain N` prints it.")
      .def("to_json", &VectorResult::json,
           "The vector's entry of `recode conform --json`'s results, as Python data.")
      .def("__str__", [](const VectorResult& r) { return r.text(4); })
      .def("__repr__", &repr);
}

void bindReport(py::module_& m) {
  py::class_<Report>(m, "Report",
                     "A whole run: what `recode conform` reports, as text (str()), JSON, JUnit, "
                     "HTML and a baseline.")
      .def_property_readonly("backend", [](const Report& r) { return r.report().backend; })
      .def_property_readonly(
          "vectors", [](const Report& r) { return resultsOf(r.run); },
          "Every vector's VectorResult, in the order run.")
      .def_property_readonly(
          "failures", &failuresOf,
          "The vectors that fail the run (failed, unexpectedly passed, nondeterministic).")
      .def_property_readonly(
          "passed", [](const Report& r) { return r.report().passed(); },
          "No error and no vector that fails the run (`recode conform`'s exit status 0).")
      .def_property_readonly("counts", &countsOf)
      .def_property_readonly(
          "behaves_like", [](const Report& r) { return readingNames(r.report().behavesLike); },
          "The kit's wrong readings whose answers equal the back end's on every vector.")
      .def_property_readonly(
          "verdict", [](const Report& r) { return conf::verdict(r.report()); },
          "'behaves like: ...' or the stages the failing vectors depart at; '' when all passed.")
      .def_property_readonly(
          "fingerprint", [](const Report& r) { return conf::describe(r.report().fingerprint); },
          "Which of the APIs' freedoms the back end takes, as the report's lines.")
      .def_property_readonly("error", [](const Report& r) { return noneIfEmpty(r.report().error); })
      .def_property_readonly(
          "error_kind",
          [](const Report& r) {
            return r.report().errorKind
                       ? std::optional<std::string>(conf::toString(*r.report().errorKind))
                       : std::nullopt;
          })
      .def_property_readonly("error_vector",
                             [](const Report& r) { return noneIfEmpty(r.report().errorVector); })
      .def("text", &Report::text, py::arg("explain") = 4,
           "What `recode conform --explain N` prints.")
      .def("summary", &summaryOf,
           "The closing lines: counts, the named reading or the stages, the fingerprint.")
      .def("to_json", &reportJson,
           "What `recode conform --json` prints; keyword arguments add top-level strings (the "
           "program adds exec=COMMAND).")
      .def(
          "to_junit", [](const Report& r) { return conf::toJunit(r.report()); },
          "What `recode conform --junit FILE` writes.")
      .def(
          "to_html", [](const Report& r) { return conf::toHtml(r.report()); },
          "What `recode conform --html FILE` writes.")
      .def(
          "to_baseline", [](const Report& r) { return conf::toBaseline(r.report()); },
          "What `recode conform --write-baseline FILE` writes.")
      .def("__str__", [](const Report& r) { return r.text(4); })
      .def("__repr__", &reportRepr);
}

}  // namespace

void bindConformance(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "conformance",
      "The conformance suite for a depth/stencil back end written in Python "
      "(docs/conformance.md, docs/api.md#the-conformance-kit-in-python): the golden vectors, "
      "check() of one answer and run() of a whole back end, with the reports of `recode "
      "conform`.");
  py::register_exception<raster::FormatError>(m, "FormatError", PyExc_ValueError);
  refusedType = py::register_exception<RefusedTag>(m, "Refused", PyExc_Exception);
  refusedType.attr("__doc__") =
      "Raise it from a back end to refuse a stream (rasterization.md section 2), with the "
      "reason as its message: the vector fails at the stage 'validation'.";

  bindVector(m);
  m.def(
      "golden_dir", []() { return defaultGoldenDir().string(); },
      "The directory vectors() reads when given none: $RECODE_GOLDEN_DIR, else the source "
      "tree's data/golden this module was built from, else share/recode/golden under the "
      "install prefix; FileNotFoundError when none exists.");
  m.def(
      "vectors",
      [](const std::optional<py::object>& directory) {
        return readVectors(goldenDirOf(directory));
      },
      py::arg("directory") = py::none(),
      "The golden vectors under `directory` (every *.json, recursively, sorted by path), or "
      "under golden_dir() when it is None: a list of Vector.");
  bindExplanation(m);
  bindVectorResult(m);
  bindReport(m);

  m.def("check", &checkAnswer, py::arg("vector"), py::arg("depth") = py::none(),
        py::arg("stencil") = py::none(), py::kw_only(), py::arg("refused") = py::none(),
        py::arg("explain") = 4096, py::arg("baseline_stage") = py::none(),
        "Checks one answer to `vector`: depth and stencil as (height, width) arrays (row 0 the "
        "bottom row) or flat, bottom row first, of integers (depth 0..16777215, stencil 0..255); "
        "or refused='why'. Returns a VectorResult with what `recode conform` says of that vector "
        "run alone: the bad pixels, the stage, the contract's section, the APIs' verdicts, the "
        "first `explain` bad pixels explained, the readings named. `baseline_stage`: the stage a "
        "baseline expects it to fail at.");
  m.def("run", &runBackend, py::arg("backend"), py::arg("vectors") = py::none(), py::kw_only(),
        py::arg("name") = py::none(), py::arg("explain") = 4096, py::arg("repeat") = 1,
        py::arg("baseline") = py::none(),
        "Runs the suite on a back end in this process: `backend(width, height, commands)` "
        "(commands as Vector.commands) returns (depth, stencil) as check() takes them, or raises "
        "Refused. `vectors`: a directory, a list of Vector, or None for golden_dir(). `name`: the "
        "back end's name in the reports (default: the callable's __name__). `baseline`: a file "
        "of expected failures (NAME,STAGE lines) or a dict {name: stage}. Returns a Report. An "
        "answer of the wrong shape or range ends the run with the report's error (kind "
        "'malformed'), as in `recode conform`; any other exception from the back end "
        "propagates.");
}

}  // namespace recode::python
