#include "verify/verify_report.hpp"

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "recode/io/printable.hpp"

namespace recode::app {

namespace {

using nlohmann::ordered_json;

std::string embreeLine(const verify::EmbreeCounts& c) {
  std::ostringstream s;
  s << c.pixels << " px: " << c.agree << " agree, " << c.ties << " depth ties, " << c.edges
    << " edge samples, " << c.unexplained << " unexplained";
  return s.str();
}

std::string glLine(const verify::GlParityCounts& c) {
  std::ostringstream s;
  s << c.pixels << " px: " << c.identical << " identical, " << c.depthTies << " depth ties, "
    << c.unexplained << " unexplained";
  return s.str();
}

std::string glExactLine(const verify::ExactParityCounts& c) {
  std::ostringstream s;
  s << c.pixels << " px: " << c.identical << " identical, " << c.different << " different";
  return s.str();
}

void printDifferences(std::ostream& out, const std::vector<verify::GlDifference>& differences) {
  for (const verify::GlDifference& d : differences)
    out << "          command " << d.command << " pixel (" << d.x << ", " << d.y << "): stencil "
        << int{d.referenceStencil} << " vs " << int{d.candidateStencil} << ", depth "
        << d.referenceDepth << " vs " << d.candidateDepth << '\n';
}

bool worthShowing(const verify::PairVerification& p) {
  return !p.passed() || (p.cgal && p.cgal->verdict != verify::VerdictCheck::Agree);
}

void printPair(std::ostream& out, const verify::PairVerification& p) {
  out << (p.passed() ? "  ok    " : "  FAIL  ") << io::printable(p.label) << ": RECODE "
      << (p.result.collide ? "collide" : "apart") << " (" << p.result.interferingPixels << " px)\n";
  if (p.embree) {
    out << "        embree " << embreeLine(p.embree->counts) << '\n';
    for (const verify::PixelDisagreement& d : p.embree->unexplained)
      out << "          pixel (" << d.x << ", " << d.y << "): device case " << d.deviceCase
          << ", oracle case " << d.oracleCase << '\n';
  }
  if (p.cgal)
    out << "        cgal   " << (p.cgal->exactIntersect ? "intersect" : "apart") << ", "
        << verify::toString(p.cgal->verdict) << ": " << p.cgal->reason << '\n';
  if (p.gl) {
    out << "        gl     " << glLine(p.gl->counts) << '\n';
    printDifferences(out, p.gl->examples);
  }
  if (p.glExact) {
    out << "        gl-exact " << glExactLine(p.glExact->counts) << '\n';
    printDifferences(out, p.glExact->examples);
  }
  if (p.vulkan) {
    out << "        vulkan " << glExactLine(p.vulkan->counts) << '\n';
    printDifferences(out, p.vulkan->examples);
  }
}

ordered_json embreeJson(const verify::EmbreeCounts& c) {
  return {{"pixels", c.pixels},
          {"agree", c.agree},
          {"ties", c.ties},
          {"edges", c.edges},
          {"unexplained", c.unexplained}};
}

ordered_json glJson(const verify::GlParityCounts& c) {
  return {{"pixels", c.pixels},
          {"identical", c.identical},
          {"depth_ties", c.depthTies},
          {"unexplained", c.unexplained}};
}

ordered_json glExactJson(const verify::ExactParityCounts& c) {
  return {{"pixels", c.pixels}, {"identical", c.identical}, {"different", c.different}};
}

ordered_json boxJson(const core::Aabb& box) {
  if (box.isEmpty())
    return nullptr;
  return ordered_json::array(
      {{box.min.x(), box.min.y(), box.min.z()}, {box.max.x(), box.max.y(), box.max.z()}});
}

ordered_json pairJson(const verify::PairVerification& p) {
  ordered_json j;
  j["label"] = p.label;
  j["collide"] = p.result.collide;
  j["interfering_pixels"] = p.result.interferingPixels;
  if (p.embree)
    j["embree"] = embreeJson(p.embree->counts);
  if (p.cgal && p.exact) {
    j["cgal"] = {{"intersect", p.exact->intersect},
                 {"volume", p.exact->volume},
                 {"box", boxJson(p.exact->box)},
                 {"verdict", verify::toString(p.cgal->verdict)},
                 {"contact_box_inside", p.cgal->contactBoxInside},
                 {"contact_box_explained", p.cgal->contactBoxExplained},
                 {"reason", p.cgal->reason}};
  }
  if (p.gl)
    j["gl"] = glJson(p.gl->counts);
  if (p.glExact)
    j["gl_exact"] = glExactJson(p.glExact->counts);
  if (p.vulkan)
    j["vulkan"] = glExactJson(p.vulkan->counts);
  j["passed"] = p.passed();
  return j;
}

// The text report's note of which Vulkan device drew (none for the vulkan device itself).
const char* vulkanDeviceLabel(verify::VulkanOracleDevice device) {
  switch (device) {
    case verify::VulkanOracleDevice::Emulated32:
      return "vulkan-32, ";
    case verify::VulkanOracleDevice::Compute:
      return "vulkan-compute, ";
    default:
      return "";
  }
}

}  // namespace

// What made the run fail, for the verdict line.
std::string failures(const VerifyRun& run) {
  std::vector<std::string> parts;
  if (!run.totals.passed())
    parts.push_back(std::to_string(run.totals.failedPairs) + " pairs with unexplained differences");
  if (run.modes && !run.modes->promisesHold()) {
    const verify::ModeCounts& m = *run.modes;
    parts.push_back(
        "modes broke their promises: conservative missed " + std::to_string(m.conservative.missed) +
        ", below the reference " + std::to_string(m.conservativeBelowReference) +
        ", extras beyond the bound " + std::to_string(m.conservativeExtrasBeyondBound) +
        "; adaptive definite apart on intersecting pairs " + std::to_string(m.adaptive.missed));
  }
  for (const auto& [name, batch] :
       {std::pair{"gl-exact", &run.glExactBatch}, std::pair{"vulkan", &run.vulkanBatch}})
    if (*batch && !(*batch)->passed())
      parts.push_back(std::to_string((*batch)->different) + " pairs batched on " + name +
                      " differ from the reference (first: " + (*batch)->firstDifferent + ")");
  std::string out;
  for (const std::string& p : parts)
    out += (out.empty() ? "" : "; ") + p;
  return out;
}

void printModes(std::ostream& out, const verify::ModeCounts& m) {
  const auto row = [&out](const char* name, const verify::MissExtra& e) {
    out << "    " << name << e.found << " found, " << e.missed << " missed, " << e.extra
        << " extra\n";
  };
  out << "  modes   " << m.pairs << " pairs, " << m.truth << " intersect (CGAL)\n";
  row("reference     ", m.reference);
  row("adaptive      ", m.adaptive);
  out << "      apart_at_limit " << m.apartAtLimit << " (" << m.apartAtLimitTrue
      << " intersect), missed by the reference but seen at finer pixels " << m.seenFiner << ", "
      << m.adaptiveRuns << " pair runs, deepest level " << m.deepestLevel << '\n';
  row("conservative  ", m.conservative);
  out << "      extras beyond the bound (CGAL) " << m.conservativeExtrasBeyondBound
      << ", apart where the reference collides " << m.conservativeBelowReference << '\n';
  out << "    time, ms: reference " << m.referenceUs / 1000 << ", adaptive " << m.adaptiveUs / 1000
      << ", conservative " << m.conservativeUs / 1000 << '\n';
}

ordered_json missExtraJson(const verify::MissExtra& e) {
  return {{"found", e.found}, {"missed", e.missed}, {"extra", e.extra}};
}

ordered_json modesJson(const verify::ModeCounts& m) {
  return {{"pairs", m.pairs},
          {"intersect", m.truth},
          {"reference", missExtraJson(m.reference)},
          {"adaptive", missExtraJson(m.adaptive)},
          {"apart_at_limit", m.apartAtLimit},
          {"apart_at_limit_intersect", m.apartAtLimitTrue},
          {"seen_at_finer_pixels", m.seenFiner},
          {"adaptive_runs", m.adaptiveRuns},
          {"deepest_level", m.deepestLevel},
          {"conservative", missExtraJson(m.conservative)},
          {"conservative_extras_beyond_bound", m.conservativeExtrasBeyondBound},
          {"conservative_below_reference", m.conservativeBelowReference},
          {"timing_us",
           {{"reference", m.referenceUs},
            {"adaptive", m.adaptiveUs},
            {"conservative", m.conservativeUs}}}};
}

bool verifyRunPassed(const VerifyRun& run) {
  return run.totals.passed() && (!run.modes || run.modes->promisesHold()) &&
         (!run.glExactBatch || run.glExactBatch->passed()) &&
         (!run.vulkanBatch || run.vulkanBatch->passed());
}

void printVerifyReport(std::ostream& out, const VerifyRun& run, bool everyPair) {
  const verify::VerificationTotals& t = run.totals;
  out << "recode verify: " << run.source << "\n  " << t.pairs << " pairs, RECODE finds "
      << t.recodeCollisions << " colliding\n";
  bool listed = false;
  for (const verify::PairVerification& p : run.pairs)
    if (everyPair || worthShowing(p)) {
      if (!listed)
        out << (everyPair ? "pairs:\n"
                          : "pairs worth a look (failures, resolution misses, extras within "
                            "rounding):\n");
      listed = true;
      printPair(out, p);
    }
  out << "totals:\n" << std::fixed << std::setprecision(2);
  if (run.oracles.embree)
    out << "  embree  " << embreeLine(t.embree) << "  (" << t.embreeRays << " rays, "
        << t.embreeSeconds << " s)\n";
  if (run.oracles.cgal)
    out << "  cgal    " << t.cgal.pairs << " pairs: " << t.cgal.agree << " agree, "
        << t.cgal.resolutionMisses << " resolution misses, " << t.cgal.roundingExtras
        << " extras within rounding, " << t.cgal.disagree << " disagree  (" << t.cgalSeconds
        << " s)\n";
  if (run.oracles.gl)
    out << "  gl      " << glLine(t.gl) << "  (" << t.glSeconds << " s)\n";
  if (run.oracles.glExact)
    out << "  gl-exact " << glExactLine(t.glExact) << "  (" << backends::toString(run.glPlatform)
        << ", " << t.glExactSeconds << " s)\n";
  if (run.oracles.vulkan)
    out << "  vulkan  " << glExactLine(t.vulkan) << "  ("
        << vulkanDeviceLabel(run.oracles.vulkanDevice) << t.vulkanSeconds << " s)\n";
  for (const auto& [name, batch] :
       {std::pair{"gl-exact", &run.glExactBatch}, std::pair{"vulkan", &run.vulkanBatch}})
    if (*batch)
      out << "  " << name << " batched: " << (*batch)->pairs << " pairs in one batch, "
          << (*batch)->different << " different from the reference; " << (*batch)->submissions
          << " submissions, " << (*batch)->readbackBytes << " bytes read back  ("
          << (*batch)->seconds << " s)\n";
  if (run.modes)
    printModes(out, *run.modes);
  if (run.viewAxis) {
    const VerifyRun::ViewAxisTotals& v = *run.viewAxis;
    out << "  view axis " << core::toString(v.rule) << ": along x " << v.along[0] << ", y "
        << v.along[1] << ", z " << v.along[2] << " (" << v.changed
        << " not the scene's); stencil pixels read " << v.stencilPixels << " (scene axis "
        << v.sceneStencilPixels << "), time " << v.recodeUs / 1000 << " ms (scene axis "
        << v.sceneRecodeUs / 1000 << " ms)\n";
  }
  out << "verdict: " << (verifyRunPassed(run) ? "VERIFIED" : "FAILED (" + failures(run) + ")")
      << '\n';
}

ordered_json verifyRunToJson(const VerifyRun& run) {
  const verify::VerificationTotals& t = run.totals;
  ordered_json j;
  j["source"] = run.source;
  j["pairs_checked"] = t.pairs;
  j["recode_collisions"] = t.recodeCollisions;
  ordered_json pairs = ordered_json::array();
  for (std::size_t i = 0; i < run.pairs.size(); ++i) {
    pairs.push_back(pairJson(run.pairs[i]));
    if (i < run.modeChecks.size()) {
      const verify::ModeCheck& m = run.modeChecks[i];
      pairs.back()["modes"] = {{"adaptive", core::toString(m.adaptive)},
                               {"adaptive_runs", m.adaptiveRuns},
                               {"adaptive_level", m.adaptiveLevel},
                               {"conservative", m.conservativeCollide}};
    }
    if (run.viewAxis)
      pairs.back()["view_axis"] = core::toString(run.viewAxis->axes[i]);
  }
  j["pairs"] = std::move(pairs);
  if (run.oracles.embree) {
    j["embree"] = embreeJson(t.embree);
    j["embree"]["rays"] = t.embreeRays;
    j["embree"]["seconds"] = t.embreeSeconds;
  }
  if (run.oracles.cgal)
    j["cgal"] = {{"pairs", t.cgal.pairs},
                 {"agree", t.cgal.agree},
                 {"resolution_misses", t.cgal.resolutionMisses},
                 {"extras_within_rounding", t.cgal.roundingExtras},
                 {"disagree", t.cgal.disagree},
                 {"seconds", t.cgalSeconds}};
  if (run.oracles.gl) {
    j["gl"] = glJson(t.gl);
    j["gl"]["seconds"] = t.glSeconds;
  }
  if (run.oracles.glExact) {
    j["gl_exact"] = glExactJson(t.glExact);
    j["gl_exact"]["platform"] = backends::toString(run.glPlatform);
    j["gl_exact"]["seconds"] = t.glExactSeconds;
  }
  if (run.oracles.vulkan) {
    j["vulkan"] = glExactJson(t.vulkan);
    if (run.oracles.vulkanDevice == verify::VulkanOracleDevice::Emulated32)
      j["vulkan"]["device"] = "vulkan-32";
    if (run.oracles.vulkanDevice == verify::VulkanOracleDevice::Compute)
      j["vulkan"]["device"] = "vulkan-compute";
    j["vulkan"]["seconds"] = t.vulkanSeconds;
  }
  const auto batchJson = [](const BatchCheck& b) {
    return ordered_json{{"pairs", b.pairs},
                        {"different", b.different},
                        {"first_different", b.firstDifferent},
                        {"submissions", b.submissions},
                        {"readback_bytes", b.readbackBytes},
                        {"seconds", b.seconds}};
  };
  if (run.glExactBatch)
    j["gl_exact"]["batch"] = batchJson(*run.glExactBatch);
  if (run.vulkanBatch)
    j["vulkan"]["batch"] = batchJson(*run.vulkanBatch);
  if (run.modes)
    j["modes"] = modesJson(*run.modes);
  if (run.viewAxis) {
    const VerifyRun::ViewAxisTotals& v = *run.viewAxis;
    j["view_axis"] = {{"rule", core::toString(v.rule)},
                      {"along", {{"x", v.along[0]}, {"y", v.along[1]}, {"z", v.along[2]}}},
                      {"changed", v.changed},
                      {"stencil_pixels_read", v.stencilPixels},
                      {"scene_stencil_pixels_read", v.sceneStencilPixels},
                      {"timing_us", {{"chosen", v.recodeUs}, {"scene", v.sceneRecodeUs}}}};
  }
  j["passed"] = verifyRunPassed(run);
  return j;
}

}  // namespace recode::app
