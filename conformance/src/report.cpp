#include "recode/conformance/report.hpp"

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "report_assets.hpp"

namespace recode::conformance {

namespace {

using nlohmann::json;

std::string readingText(kit::Variant v) {
  for (const kit::VariantInfo& info : kit::wrongVariants()) {
    if (info.variant == v)
      return std::string(info.what) + " (" + std::string(info.name) + ")";
  }
  return std::string(kit::variantName(v));
}

// A failing vector's bad pixels against the graphics APIs: how many a native pipeline may not
// give (with each explained pixel's clause below) and how many lie within the APIs' freedom.
std::string apiText(const ApiTally& t) {
  const long long all = t.forbidden + t.withinFreedom;
  const std::string freedoms = t.freedoms == 0 ? "" : " (" + describe(t.freedoms) + ")";
  if (t.forbidden == 0)
    return "graphics APIs: every bad pixel lies within their freedom" + freedoms +
           ": a native pipeline may answer this; only this contract fixes it";
  std::string s = "graphics APIs: " + std::to_string(t.forbidden) + " of " + std::to_string(all) +
                  " bad pixels are departures the APIs forbid (on a native pipeline, a bug; "
                  "each explained pixel names its clause)";
  if (t.withinFreedom > 0)
    s += "; " + std::to_string(t.withinFreedom) + " lie within their freedom" + freedoms;
  return s;
}

std::string pixelLine(const BadPixel& p) {
  std::ostringstream o;
  o << "pixel (" << p.x << ", " << p.y << "): ";
  if (p.depthDiffers()) {
    o << "depth expected " << p.expectedDepth << ", got " << p.gotDepth << " ("
      << (p.depthUnits() > 0 ? "+" : "") << p.depthUnits() << " units)";
  }
  if (p.depthDiffers() && p.stencilDiffers())
    o << "; ";
  if (p.stencilDiffers()) {
    o << "stencil expected " << static_cast<int>(p.expectedStencil) << ", got "
      << static_cast<int>(p.gotStencil);
  }
  return o.str();
}

void indented(std::ostream& out, const std::string& text, const std::string& pad) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    out << pad << line << '\n';
}

// " (baseline expects coverage, now depth test)" for a failure at another stage than the
// baseline's; empty otherwise.
std::string baselineNote(const VectorReport& v) {
  if (v.status != Status::Failed || !v.baselineStage || !v.stage)
    return {};
  return " (baseline expects " + std::string(toString(*v.baselineStage)) + ", now " +
         std::string(toString(*v.stage)) + ")";
}

std::map<Stage, int> stageCounts(const SuiteReport& report) {
  std::map<Stage, int> counts;
  for (const VectorReport& v : report.vectors) {
    if (v.stage && (v.status == Status::Failed || v.status == Status::ExpectedFailure))
      ++counts[*v.stage];
  }
  return counts;
}

}  // namespace

void printVectorLine(std::ostream& out, const VectorReport& v) {
  out << "  " << toString(v.status) << "  " << v.name << baselineNote(v);
  if (v.status == Status::UnexpectedPass)
    out << ": passes, but the baseline lists it as failing (remove it from the baseline)";
  if (v.status == Status::Nondeterministic)
    out << ": two runs of the vector gave different answers";
  if (v.stage) {
    if (!v.refused.empty())
      out << ": the back end refused the stream: " << v.refused;
    else
      out << ": " << v.depthPixels << " depth, " << v.stencilPixels << " stencil pixels differ";
  }
  out << '\n';
}

bool hasDetails(const VectorReport& v) {
  return v.stage.has_value();
}

void printVector(std::ostream& out, const VectorReport& v, std::size_t pixels) {
  printVectorLine(out, v);
  if (!v.stage)
    return;
  out << "        stage: " << toString(*v.stage) << ", " << contractSection(*v.stage) << '\n';
  if (v.api)
    out << "        " << apiText(*v.api) << '\n';
  for (std::size_t i = 0; i < v.explained.size() && i < pixels; ++i) {
    const PixelExplanation& e = v.explained[i];
    out << "        " << pixelLine(e.pixel) << '\n';
    out << "          " << toString(e.stage) << ": " << e.why << '\n';
    if (i < v.apiVerdicts.size())
      out << "          APIs: " << describe(v.apiVerdicts[i], e.pixel, e.stage) << '\n';
    out << "          the contract's history of the pixel:\n";
    indented(out, describe(e.history), "            ");
  }
  if (v.badPixelCount > static_cast<long long>(std::min(pixels, v.explained.size()))) {
    out << "        (" << v.badPixelCount
        << " bad pixels in all; the JSON and HTML reports give every one"
        << ")\n";
  }
}

std::string verdict(const SuiteReport& report) {
  if (!report.behavesLike.empty()) {
    std::string s = "behaves like: ";
    for (std::size_t i = 0; i < report.behavesLike.size(); ++i)
      s += (i == 0 ? "" : "; or ") + readingText(report.behavesLike[i]);
    return s;
  }
  const std::map<Stage, int> counts = stageCounts(report);
  if (counts.empty())
    return {};
  std::string s = "behaves like none of the kit's wrong readings; failing vectors first depart at ";
  bool first = true;
  for (const auto& [stage, n] : counts) {
    s += (first ? "" : ", ") + std::string(toString(stage)) + " (" + std::to_string(n) + ", " +
         std::string(contractSection(stage)) + ")";
    first = false;
  }
  return s;
}

void printSummary(std::ostream& out, const SuiteReport& report) {
  out << report.vectors.size() << " vectors: " << report.count(Status::Passed) << " passed, "
      << report.count(Status::Failed) << " failed";
  if (const int n = report.changedStages(); n > 0)
    out << " (" << n << " at another stage than the baseline's)";
  if (const int n = report.count(Status::ExpectedFailure); n > 0)
    out << ", " << n << " expected failures";
  if (const int n = report.count(Status::UnexpectedPass); n > 0)
    out << ", " << n << " unexpected passes";
  if (const int n = report.count(Status::Nondeterministic); n > 0)
    out << ", " << n << " nondeterministic";
  out << '\n';
  if (const std::string v = verdict(report); !v.empty())
    out << v << '\n';
  int forbidding = 0;
  for (const VectorReport& v : report.vectors)
    forbidding += v.api && v.api->forbidden > 0 ? 1 : 0;
  if (report.count(Status::Failed) + report.count(Status::ExpectedFailure) > 0 &&
      !report.fingerprint.empty())
    out << "departures the graphics APIs forbid: " << forbidding
        << (forbidding == 1 ? " vector" : " vectors") << '\n'
        << describe(report.fingerprint);
  if (!report.error.empty()) {
    out << "error";
    if (report.errorKind)
      out << " (" << toString(*report.errorKind) << ")";
    out << ": " << report.error << '\n';
  }
}

namespace {

json historyJson(const PixelHistory& h) {
  json events = json::array();
  for (const HistoryEvent& e : h.events) {
    json j = {{"command", e.command}};
    if (e.clear) {
      const ClearEvent& c = *e.clear;
      j["clear"] = c.depth ? "depth" : "stencil";
      j["value"] = c.value;
      j["skipped"] = c.skipped;
      j["write_mask"] = c.writeMask;
      j["depth"] = {c.depthBefore, c.depthAfter};
      j["stencil"] = {c.stencilBefore, c.stencilAfter};
    }
    if (e.triangle) {
      const TriangleEvent& t = *e.triangle;
      static constexpr std::array<const char*, 5> outcomes = {
          "fragment", "degenerate", "culled", "outside the scissor", "excluded by the tie rule"};
      j["draw"] = t.draw;
      j["triangle"] = t.triangle;
      j["outcome"] = outcomes[static_cast<std::size_t>(t.outcome)];
      j["vertices_fixed"] = json::array();
      for (int k = 0; k < 3; ++k)
        j["vertices_fixed"].push_back({t.X[k], t.Y[k], static_cast<double>(t.Z[k])});
      j["area2"] = t.area2;
      j["facing"] = t.front ? "front" : "back";
      j["edges"] = json::array();
      for (const EdgeAtSample& edge : t.edges) {
        j["edges"].push_back({{"from", edge.from},
                              {"to", edge.to},
                              {"value", edge.value},
                              {"inclusive", edge.inclusive}});
      }
      if (t.outcome == TriangleOutcome::Fragment) {
        const PlaneTerms& p = t.plane;
        j["plane"] = {{"z0", p.z0},
                      {"dz1", p.dz1},
                      {"dz2", p.dz2},
                      {"e1x", p.e1x},
                      {"e1y", p.e1y},
                      {"e2x", p.e2x},
                      {"e2y", p.e2y},
                      {"a2", p.a2},
                      {"dzdx", p.dzdx},
                      {"dzdy", p.dzdy},
                      {"tx", p.tx},
                      {"ty", p.ty},
                      {"z0_plus_tx", p.z0PlusTx},
                      {"z", p.z}};
        j["quantisation"] = {{"scaled", t.quantisation.scaled},
                             {"tie", t.quantisation.tie},
                             {"q", t.quantisation.q}};
        j["stencil_test"] = {{"func", t.stencilFunc},
                             {"ref", t.stencilRef},
                             {"value_mask", t.valueMask},
                             {"passed", t.stencilPassed}};
        j["depth_test"] = {{"func", t.depthFunc}, {"passed", t.depthPassed}};
        j["op"] = {{"slot", t.opSlot}, {"op", t.op}};
        j["write_masks"] = {{"depth", t.depthWrite}, {"stencil", t.writeMask}};
        j["depth"] = {t.depthBefore, t.depthAfter};
        j["stencil"] = {t.stencilBefore, t.stencilAfter};
      }
    }
    events.push_back(std::move(j));
  }
  return {{"events", events}, {"depth", h.finalDepth}, {"stencil", h.finalStencil}};
}

json freedomNames(FreedomSet set) {
  json out = json::array();
  for (const std::string& name : namesOf(set))
    out.push_back(name);
  return out;
}

json verdictJson(const ApiVerdict& v, Stage stage) {
  json choices = json::array();
  for (const OpenChoice& c : v.choices)
    choices.push_back({{"command", c.command},
                       {"draw", c.draw},
                       {"triangle", c.triangle},
                       {"freedom", toString(c.freedom)},
                       {"how", c.how}});
  json states = json::array();
  for (const AllowedState& s : v.states)
    states.push_back({{"stencil", s.stencil}, {"depth", {s.depthLo, s.depthHi}}});
  json j = {{"allowed", v.allowed},
            {"freedoms", freedomNames(v.freedoms)},
            {"allowed_states", states},
            {"choices", choices}};
  if (!v.allowed)
    j["clause"] = apiClause(forbiddenStage(v, stage));
  return j;
}

json fingerprintJson(const std::vector<FingerprintTrait>& traits) {
  json out = json::array();
  for (const FingerprintTrait& t : traits) {
    json candidates = json::array();
    for (const FingerprintCandidate& c : t.candidates)
      candidates.push_back({{"reading", c.name},
                            {"what", c.what},
                            {"pixels_for", c.pixelsFor},
                            {"pixels_against", c.pixelsAgainst},
                            {"pixels_neither", c.pixelsNeither},
                            {"vectors_for", c.vectorsFor},
                            {"vectors_against", c.vectorsAgainst}});
    json trait = {{"freedom", t.freedom}, {"verdict", t.verdict()}, {"candidates", candidates}};
    trait["taken"] =
        t.taken < 0 ? json(nullptr) : json(t.candidates[static_cast<std::size_t>(t.taken)].name);
    out.push_back(std::move(trait));
  }
  return out;
}

json vectorJson(const VectorReport& v) {
  json j = {
      {"file", v.name},   {"status", toString(v.status)}, {"passed", v.status == Status::Passed},
      {"width", v.width}, {"height", v.height},           {"seconds", v.seconds}};
  if (v.requirement) {
    const auto by = [](const BufferRequirement& b) {
      return b.byGraphicsApis ? "graphics APIs" : "contract only";
    };
    j["required_by"] = {{"depth", by(v.requirement->depth)},
                        {"stencil", by(v.requirement->stencil)}};
    j["api_latitudes"] = {{"depth", v.requirement->depth.latitudes},
                          {"stencil", v.requirement->stencil.latitudes}};
  }
  if (v.api)
    j["api"] = {{"forbidden_pixels", v.api->forbidden},
                {"freedom_pixels", v.api->withinFreedom},
                {"freedoms", freedomNames(v.api->freedoms)}};
  if (v.baselineStage)
    j["baseline_stage"] = toString(*v.baselineStage);
  if (!v.stage)
    return j;
  j["stage"] = toString(*v.stage);
  j["contract_section"] = contractSection(*v.stage);
  if (!v.refused.empty())
    j["refused"] = v.refused;
  j["depth_pixels"] = v.depthPixels;
  j["stencil_pixels"] = v.stencilPixels;
  if (!v.badPixels.empty()) {
    const BadPixel& p = v.badPixels.front();
    const bool depth = p.depthDiffers();
    j["first_difference"] = {{"x", p.x},
                             {"y", p.y},
                             {"buffer", depth ? "depth" : "stencil"},
                             {"expected", depth ? p.expectedDepth : p.expectedStencil},
                             {"got", depth ? p.gotDepth : p.gotStencil}};
  }
  j["bad_pixels"] = json::array();
  for (const BadPixel& p : v.badPixels) {
    j["bad_pixels"].push_back({{"x", p.x},
                               {"y", p.y},
                               {"depth", {p.expectedDepth, p.gotDepth}},
                               {"stencil", {p.expectedStencil, p.gotStencil}},
                               {"depth_units", p.depthUnits()}});
  }
  j["explained"] = json::array();
  for (const PixelExplanation& e : v.explained) {
    json x = {{"x", e.pixel.x},
              {"y", e.pixel.y},
              {"stage", toString(e.stage)},
              {"contract_section", contractSection(e.stage)},
              {"why", e.why},
              {"rule", e.rule},
              {"history", historyJson(e.history)}};
    if (e.sameAsReading)
      x["same_as_reading"] = kit::variantName(*e.sameAsReading);
    const std::size_t i = j["explained"].size();
    if (i < v.apiVerdicts.size())
      x["api"] = verdictJson(v.apiVerdicts[i], e.stage);
    j["explained"].push_back(std::move(x));
  }
  return j;
}

std::string xmlEscaped(std::string_view s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // XML 1.0 forbids most control characters even escaped.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t')
          out += '?';
        else
          out += c;
    }
  }
  return out;
}

std::string vectorText(const VectorReport& v, std::size_t pixels) {
  std::ostringstream o;
  printVector(o, v, pixels);
  return o.str();
}

}  // namespace

std::string toJson(const SuiteReport& report,
                   const std::vector<std::pair<std::string, std::string>>& fields) {
  json list = json::array();
  for (const VectorReport& v : report.vectors)
    list.push_back(vectorJson(v));
  json readings = json::array();
  for (kit::Variant r : report.behavesLike)
    readings.push_back(kit::variantName(r));
  json j = {{"backend", report.backend},
            {"vectors", report.vectors.size()},
            {"passed", report.count(Status::Passed)},
            {"failed", report.count(Status::Failed)},
            {"expected_failures", report.count(Status::ExpectedFailure)},
            {"unexpected_passes", report.count(Status::UnexpectedPass)},
            {"nondeterministic", report.count(Status::Nondeterministic)},
            {"behaves_like", readings},
            {"verdict", verdict(report)},
            {"results", list}};
  if (!report.fingerprint.empty())
    j["fingerprint"] = fingerprintJson(report.fingerprint);
  if (!report.error.empty()) {
    j["error"] = report.error;
    if (report.errorKind)
      j["error_kind"] = toString(*report.errorKind);
    if (!report.errorVector.empty())
      j["error_vector"] = report.errorVector;
  }
  for (const auto& [key, value] : fields)
    j[key] = value;
  return j.dump(1) + "\n";
}

std::string toJunit(const SuiteReport& report) {
  std::ostringstream o;
  const int failures = report.count(Status::Failed) + report.count(Status::UnexpectedPass);
  const int errors = report.count(Status::Nondeterministic) + (report.error.empty() ? 0 : 1);
  double seconds = 0;
  for (const VectorReport& v : report.vectors)
    seconds += v.seconds;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites>\n<testsuite name=\"recode conform: " << xmlEscaped(report.backend)
    << "\" tests=\"" << report.vectors.size() + (report.error.empty() ? 0 : 1) << "\" failures=\""
    << failures << "\" errors=\"" << errors << "\" skipped=\""
    << report.count(Status::ExpectedFailure) << "\" time=\"" << seconds << "\">\n";
  for (const VectorReport& v : report.vectors) {
    o << " <testcase classname=\"recode.conform\" name=\"" << xmlEscaped(v.name) << "\" time=\""
      << v.seconds << "\"";
    const std::string text = xmlEscaped(vectorText(v, 4));
    const std::string stage = v.stage ? std::string(toString(*v.stage)) : std::string();
    switch (v.status) {
      case Status::Passed:
        o << "/>\n";
        continue;
      case Status::Failed:
        o << ">\n  <failure message=\""
          << xmlEscaped(stage + ": " + std::string(contractSection(*v.stage)) + baselineNote(v))
          << "\">" << text << "</failure>\n";
        break;
      case Status::ExpectedFailure:
        o << ">\n  <skipped message=\"expected failure (baseline)\">" << text << "</skipped>\n";
        break;
      case Status::UnexpectedPass:
        o << ">\n  <failure message=\"unexpected pass: remove it from the baseline\"/>\n";
        break;
      case Status::Nondeterministic:
        o << ">\n  <error message=\"nondeterministic: two runs gave different answers\">" << text
          << "</error>\n";
        break;
    }
    o << " </testcase>\n";
  }
  // The run's error is the test case of the vector the back end broke on (or "back end" when it
  // broke before any), typed by how it broke.
  if (!report.error.empty()) {
    o << " <testcase classname=\"recode.conform\" name=\""
      << xmlEscaped(report.errorVector.empty() ? "back end" : report.errorVector)
      << "\">\n  <error";
    if (report.errorKind)
      o << " type=\"" << toString(*report.errorKind) << "\"";
    o << " message=\"" << xmlEscaped(report.error.substr(0, report.error.find('\n'))) << "\">"
      << xmlEscaped(report.error) << "</error>\n </testcase>\n";
  }
  o << "</testsuite>\n</testsuites>\n";
  return o.str();
}

namespace {

// The colour of a bad pixel that was not explained.
constexpr const char* kUnexplainedColour = "#bbbbbb";

// The vector's frame as a canvas with every bad pixel coloured by the stage of its explanation
// (grey where it was not explained), y up as in the buffers. The mask travels as runs of
// "stage:count" over the pixels in buffer order (-1: a good pixel), which the page's script
// paints: a few bytes for a frame of any size, where an element per pixel would not scale.
std::string errorMask(const VectorReport& v) {
  std::map<std::pair<int, int>, Stage> stages;
  for (const PixelExplanation& e : v.explained)
    stages[{e.pixel.x, e.pixel.y}] = e.stage;
  const int unexplained = static_cast<int>(allStages().size());  // after every stage
  std::ostringstream runs;
  int current = -1;
  long long length = 0, at = 0;
  const auto flush = [&](int next, long long pixel) {
    if (length > 0)
      runs << current << ':' << length << ' ';
    current = next;
    length = 0;
    at = pixel;
  };
  for (const BadPixel& p : v.badPixels) {
    const long long pixel = static_cast<long long>(p.y) * v.width + p.x;
    if (pixel > at)
      flush(-1, at), length = pixel - at;
    const auto it = stages.find({p.x, p.y});
    const int code = it == stages.end() ? unexplained : static_cast<int>(it->second);
    if (code != current)
      flush(code, pixel);
    ++length;
    at = pixel + 1;
  }
  flush(-1, at);
  const int longest = std::max(v.width, v.height);
  const int scale = longest >= 256 ? 1 : 256 / longest;
  std::ostringstream o;
  o << "<canvas class=\"mask\" width=\"" << v.width << "\" height=\"" << v.height
    << "\" style=\"width:" << std::min(1024, v.width * scale)
    << "px;height:" << std::min(1024, v.height * scale) << "px\" data-runs=\"" << runs.str()
    << "\"></canvas>";
  return o.str();
}

// The colours the page's script paints the masks with: the stages' in order, then the
// unexplained pixels'.
std::string maskColours() {
  std::string colours;
  for (const StageInfo& s : allStages())
    colours += std::string(s.colour) + " ";
  return colours + kUnexplainedColour;
}

}  // namespace

std::string toHtml(const SuiteReport& report) {
  // Histories shown per vector: the mask shows every bad pixel, and --json has every history.
  constexpr std::size_t kHtmlHistories = 16;
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>recode conform: "
    << xmlEscaped(report.backend) << "</title>\n<style>\n"
    << kReportCss << "</style></head>\n<body data-stage-colours=\"" << maskColours() << "\">\n"
    << "<h1>recode conform: " << xmlEscaped(report.backend) << "</h1>\n<pre>";
  {
    std::ostringstream summary;
    printSummary(summary, report);
    o << xmlEscaped(summary.str());
  }
  o << "</pre>\n<p class=\"key\">Error masks by stage:";
  for (const StageInfo& s : allStages())
    o << "<span style=\"background:" << s.colour << "\"></span>" << s.name;
  o << "<span style=\"background:" << kUnexplainedColour << "\"></span>not explained</p>\n";
  for (const VectorReport& v : report.vectors) {
    if (!v.stage && v.status == Status::Passed)
      continue;
    o << "<section><h2 class=\"" << xmlEscaped(std::string(toString(v.status)).substr(0, 10))
      << "\">" << xmlEscaped(std::string(toString(v.status))) << " " << xmlEscaped(v.name)
      << "</h2>\n<p>" << xmlEscaped(v.description) << "</p>\n";
    if (v.stage && v.refused.empty())
      o << errorMask(v) << "\n";
    o << "<pre>" << xmlEscaped(vectorText(v, kHtmlHistories)) << "</pre></section>\n";
  }
  o << "<h2>Passed</h2><p>";
  for (const VectorReport& v : report.vectors) {
    if (v.status == Status::Passed)
      o << "<span class=\"pass\">" << xmlEscaped(v.name) << "</span> ";
  }
  o << "</p>\n<script>\n" << kReportJs << "</script>\n</body></html>\n";
  return o.str();
}

}  // namespace recode::conformance
