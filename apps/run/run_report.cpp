#include "run/run_report.hpp"

#include <iomanip>
#include <sstream>

#include "recode/io/printable.hpp"
#include "recode/raster/device.hpp"

namespace recode::app {

namespace {

using nlohmann::ordered_json;

ordered_json vec(const Eigen::Vector3d& v) {
  return ordered_json::array({v.x(), v.y(), v.z()});
}

const core::HierarchyNode& leaf(const core::Simulation& sim, int object, int node) {
  return sim.objects()[static_cast<std::size_t>(object)].nodes()[static_cast<std::size_t>(node)];
}

const std::string& objectName(const core::Simulation& sim, int object) {
  return sim.objects()[static_cast<std::size_t>(object)].name();
}

// The vulkan-compute device's stage times, one column each (in milliseconds).
std::string stageColumns() {
  std::string columns;
  for (const char* name : raster::TransferCounters::kStageNames)
    columns += std::string(columns.empty() ? "" : ",") + "stage_ms_" + name;
  return columns;
}

}  // namespace

ordered_json frameToJson(const core::Simulation& sim, const core::FrameReport& frame) {
  ordered_json j;
  j["frame"] = frame.frame;
  ordered_json pairs = ordered_json::array();
  for (const core::LeafContact& c : frame.contacts) {
    ordered_json p;
    p["a"] = objectName(sim, c.objectA);
    p["b"] = objectName(sim, c.objectB);
    p["leaf_a"] = leaf(sim, c.objectA, c.leafA).path;
    p["leaf_b"] = leaf(sim, c.objectB, c.leafB).path;
    p["object_a"] = c.objectA;
    p["object_b"] = c.objectB;
    p["interfering_pixels"] = c.result.interferingPixels;
    if (sim.viewAxisRule() != core::ViewAxisRule::Scene)
      p["view_axis"] = core::toString(c.viewAxis);
    ordered_json contact;
    contact["pixels"] = c.result.contact.pixels;
    contact["area"] = c.result.contact.area;
    contact["max_depth"] = c.result.contact.maxDepth;
    contact["box"] =
        c.result.contact.box.isEmpty()
            ? ordered_json(nullptr)
            : ordered_json::array({vec(c.result.contact.box.min), vec(c.result.contact.box.max)});
    contact["collapsed_pixels"] = c.result.contact.collapsedPixels;
    p["contact"] = contact;
    pairs.push_back(p);
  }
  j["pairs"] = pairs;
  j["object_pairs"] = frame.objectPairs;
  j["box_tests"] = frame.boxTests;
  j["pair_tests"] = frame.pairTests;
  if (sim.pairMode() == core::PairMode::SkipApart)
    j["pair_tests_skipped"] = frame.pairTestsSkipped;
  j["stencil_pixels_read"] = frame.stencilPixelsRead;
  j["depth_pixels_read"] = frame.depthPixelsRead;
  j["frame_us"] = frame.frameUs;
  j["collision_us"] = frame.collisionUs;
  return j;
}

ordered_json statisticsToJson(const core::RunStatistics& s, core::PairMode mode) {
  ordered_json j;
  j["NTR"] = s.triangles;
  j["TNF"] = s.frames;
  j["TTF_s"] = s.totalFrameS;
  j["ATF_ms"] = s.meanFrameMs;
  j["DTF_ms"] = s.sdFrameMs;
  j["TTC_s"] = s.totalCollisionS;
  j["ATC_ms"] = s.meanCollisionMs;
  j["DTC_ms"] = s.sdCollisionMs;
  j["object_pairs"] = s.objectPairs;
  j["box_tests"] = s.boxTests;
  j["pair_tests"] = s.pairTests;
  if (mode == core::PairMode::SkipApart)
    j["pair_tests_skipped"] = s.pairTestsSkipped;
  j["stencil_pixels_read"] = s.stencilPixelsRead;
  j["depth_pixels_read"] = s.depthPixelsRead;
  j["contacts"] = s.contacts;
  j["frames_with_contact"] = s.framesWithContact;
  j["first_contact_frame"] =
      s.firstContactFrame < 0 ? ordered_json(nullptr) : ordered_json(s.firstContactFrame);
  return j;
}

ordered_json runToJson(const RunDescription& run, const core::Simulation& sim) {
  ordered_json j;
  j["scene"] = run.scene;
  j["source"] = run.source;
  ordered_json objects = ordered_json::array();
  for (const core::ObjectTree& o : sim.objects()) {
    ordered_json e;
    e["name"] = o.name();
    e["blocks"] = o.leaves().size();
    e["triangles"] = o.triangleCount();
    objects.push_back(e);
  }
  j["objects"] = objects;
  j["axis"] = core::toString(sim.axis());
  if (sim.viewAxisRule() != core::ViewAxisRule::Scene)
    j["view_axis_rule"] = core::toString(sim.viewAxisRule());
  j["pixel_size"] = sim.pixelSize();
  j["frames_requested"] = run.frames;
  j["stop_on_contact"] = run.stopOnContact;
  if (run.mode != core::PairMode::Reference)
    j["mode"] = core::toString(run.mode);
  return j;
}

void printRunHeader(std::ostream& out, const RunDescription& run, const core::Simulation& sim) {
  std::size_t blocks = 0;
  for (const core::ObjectTree& o : sim.objects())
    blocks += o.leaves().size();
  out << "recode run: " << io::printable(run.scene) << " (" << run.source << "), "
      << sim.objects().size() << " objects, " << blocks << " blocks, " << sim.triangleCount()
      << " triangles\n"
      << "  view along " << core::toString(sim.axis());
  if (sim.viewAxisRule() != core::ViewAxisRule::Scene)
    out << " (per pair: " << core::toString(sim.viewAxisRule()) << ")";
  out << ", pixel size " << sim.pixelSize() << ", frames 0.." << run.frames - 1
      << (run.stopOnContact ? " (stop at first contact)" : "") << "\n";
  if (run.mode != core::PairMode::Reference)
    out << "  every block pair decided in the " << core::toString(run.mode) << " mode\n";
}

void printFrame(std::ostream& out, const core::Simulation& sim, const core::FrameReport& frame) {
  if (frame.contacts.empty())
    return;
  out << "frame " << frame.frame << ": " << frame.contacts.size() << " contact"
      << (frame.contacts.size() == 1 ? "" : "s") << " (" << frame.pairTests << " pair tests)\n";
  for (const core::LeafContact& c : frame.contacts) {
    // Paths are made of the scene's names: echoed with control characters escaped.
    out << "  " << io::printable(leaf(sim, c.objectA, c.leafA).path) << "  x  "
        << io::printable(leaf(sim, c.objectB, c.leafB).path) << ": " << c.result.interferingPixels
        << " px, area " << c.result.contact.area;
    if (!c.result.contact.box.isEmpty())
      out << ", depth " << c.result.contact.maxDepth;
    if (sim.viewAxisRule() != core::ViewAxisRule::Scene)
      out << ", along " << core::toString(c.viewAxis);
    out << "\n";
  }
}

void printStatistics(std::ostream& out, const core::RunStatistics& s, core::PairMode mode) {
  const auto oldFlags = out.flags();
  const auto oldPrecision = out.precision();
  out << "statistics (the paper's Table 2; nothing is displayed, so a frame is posing the "
         "nodes plus collision detection):\n"
      << "  NTR " << s.triangles << " triangles, TNF " << s.frames << " frames\n"
      << std::fixed << std::setprecision(3) << "  TTF " << s.totalFrameS << " s   ATF "
      << s.meanFrameMs << " ms   DTF " << s.sdFrameMs << " ms\n"
      << "  TTC " << s.totalCollisionS << " s   ATC " << s.meanCollisionMs << " ms   DTC "
      << s.sdCollisionMs << " ms\n";
  out.flags(oldFlags);
  out.precision(oldPrecision);
  out << "  object pairs " << s.objectPairs << ", box tests " << s.boxTests << ", pair tests "
      << s.pairTests
      << (mode == core::PairMode::SkipApart
              ? " (" + std::to_string(s.pairTestsSkipped) + " proven apart, not drawn)"
              : std::string())
      << ", stencil pixels read " << s.stencilPixelsRead << ", depth pixels read "
      << s.depthPixelsRead << "\n"
      << "  contacts " << s.contacts << " in " << s.framesWithContact << " frame"
      << (s.framesWithContact == 1 ? "" : "s");
  if (s.firstContactFrame >= 0)
    out << ", first at frame " << s.firstContactFrame;
  out << "\n";
}

std::string csvHeader(core::PairMode mode) {
  return std::string("frame,frame_us,collision_us,object_pairs,box_tests,pair_tests,") +
         (mode == core::PairMode::SkipApart ? "pair_tests_skipped," : "") +
         "stencil_pixels_read,depth_pixels_read,contacts,device_wait_us,submissions,dispatches," +
         stageColumns() + "\n";
}

std::string csvRow(const core::FrameReport& f, core::PairMode mode) {
  std::ostringstream row;
  row << f.frame << ',' << f.frameUs << ',' << f.collisionUs << ',' << f.objectPairs << ','
      << f.boxTests << ',' << f.pairTests << ',';
  if (mode == core::PairMode::SkipApart)
    row << f.pairTestsSkipped << ',';
  row << f.stencilPixelsRead << ',' << f.depthPixelsRead << ',' << f.contacts.size() << ','
      << f.deviceWaitUs << ',' << f.submissions << ',' << f.dispatches;
  for (const double us : f.stageUs)
    row << ',' << us / 1000.0;
  row << '\n';
  return row.str();
}

}  // namespace recode::app
