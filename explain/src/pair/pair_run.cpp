#include "pair/pair_run.hpp"

#include <array>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "output/timing_fields.hpp"
#include "pair/layered_report.hpp"
#include "recode/refine/adaptive.hpp"
#include "recode/refine/proven_apart.hpp"

namespace recode::explain {

namespace {

nlohmann::ordered_json boxJson(const core::Aabb& box) {
  if (box.isEmpty())
    return nullptr;
  return {{box.min.x(), box.min.y(), box.min.z()}, {box.max.x(), box.max.y(), box.max.z()}};
}

// The --mode object: what the adaptive, conservative or skip-apart mode decided, beside the
// reference run's report (which stays as it was).
nlohmann::ordered_json modeJson(core::PairMode mode, raster::DepthStencilDevice& device,
                                const PairSetup& setup, const core::PairRequest& request,
                                const core::PairBlock& a, const core::PairBlock& b,
                                const core::PairResult& reference) {
  nlohmann::ordered_json j;
  j["name"] = core::toString(mode);
  if (mode == core::PairMode::SkipApart) {
    // Proven apart: nothing drawn. Otherwise the skip-apart mode's answer is the reference run's.
    const bool apart = core::provenApart(a, b, request.frame);
    j["verdict"] = apart || !reference.collide ? "apart" : "collide";
    j["proven_apart"] = apart;
    j["interfering_pixels"] = apart ? 0 : reference.interferingPixels;
    return j;
  }
  if (mode == core::PairMode::Conservative) {
    const core::ConservativeResult r = core::collideConservative(device, setup.a, setup.b, request);
    j["verdict"] = r.pair.collide ? "collide" : "apart";
    j["growth"] = {r.growth.x(), r.growth.y(), r.growth.z()};
    j["interfering_pixels"] = r.pair.interferingPixels;
    j["contact_box"] = boxJson(r.pair.contact.box);
    return j;
  }
  core::AdaptivePairTester tester;
  const core::AdaptiveResult r = tester.collide(device, setup.a, setup.b, request);
  j["verdict"] = core::toString(r.verdict);
  j["runs"] = r.runs;
  j["deepest_level"] = r.deepestLevel;
  j["finest_pixel"] = r.finestPixel;
  if (r.contact) {
    const core::FrameSpec& f = r.contactFrame;
    j["contact_frame"] = {{"width", f.width},
                          {"height", f.height},
                          {"window", {f.window.umin, f.window.vmin, f.window.umax, f.window.vmax}}};
    j["interfering_pixels"] = r.contact->interferingPixels;
    j["contact_box"] = boxJson(r.contact->contact.box);
    j["contact_area"] = r.contact->contact.area;
  }
  if (r.verdict == core::PairVerdict::ApartAtLimit)
    j["unresolved_box"] = boxJson(r.unresolved);
  return j;
}

void printMode(std::ostream& out, const nlohmann::ordered_json& j) {
  out << "mode " << j["name"].get<std::string>() << ": " << j["verdict"].get<std::string>();
  for (const char* key :
       {"runs", "deepest_level", "finest_pixel", "interfering_pixels", "proven_apart"})
    if (j.contains(key))
      out << ", " << key << " " << j[key].dump();
  out << '\n';
}

// "X,Y" inside the frame, or std::invalid_argument naming the option, the value and the rule.
std::array<int, 2> parsePixel(const std::string& text, const core::FrameSpec& frame) {
  int x = -1, y = -1;
  char comma = 0;
  std::istringstream in(text);
  const auto bad = [&](const std::string& rule) {
    return std::invalid_argument("--pixel " + text + ": " + rule);
  };
  if (!(in >> x >> comma >> y) || comma != ',' || !(in >> std::ws).eof())
    throw bad("expected X,Y (two whole numbers)");
  if (x < 0 || y < 0 || x >= frame.width || y >= frame.height)
    throw bad("outside the " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
              " frame (x from the left, y from the bottom, from 0)");
  return {x, y};
}

// Both observers of the reference run, each told of every step.
class TwoObservers final : public core::PairObserver {
 public:
  TwoObservers(core::PairObserver* first, core::PairObserver* second)
      : first_(first), second_(second) {}
  void afterStep(core::PairStep step, raster::DepthStencilDevice& device) override {
    if (first_)
      first_->afterStep(step, device);
    if (second_)
      second_->afterStep(step, device);
  }

 private:
  core::PairObserver* first_;
  core::PairObserver* second_;
};

// The options only RECODE's passes have, refused for a pair with a closed mesh.
void requireReferenceOnlyOptions(const PairRunOptions& o) {
  const auto refuse = [](const std::string& option) {
    throw std::invalid_argument(option +
                                " applies to a pair of convex blocks: this pair has a closed mesh, "
                                "decided by the layered pair (docs/algorithm.md section 13)");
  };
  if (o.mode != core::PairMode::Reference)
    refuse("--mode " + std::string(core::toString(o.mode)));
  if (o.axisRule != core::ViewAxisRule::Scene)
    refuse("--view-axis " + std::string(core::toString(o.axisRule)));
}

}  // namespace

PairRun runPair(const PairRunOptions& o, const PairDeviceMaker& makeDevice,
                core::PairObserver* observer) {
  PairRun run{loadPairSetup(o.scene, o.overrides), {}, {}, {}, o.axisRule, {}, {}};
  PairSetup& setup = run.setup;
  if (setup.layered())
    requireReferenceOnlyOptions(o);
  // Another axis than the scene's: the frame is rebuilt along it at the same pixel size.
  if (o.axisRule != core::ViewAxisRule::Scene) {
    core::Aabb bounds = core::boundingBox(setup.a);
    bounds.extend(core::boundingBox(setup.b));
    const core::ViewAxis axis = core::chooseViewAxis(
        o.axisRule, setup.frame.axis,
        core::axisChoiceInput(setup.a, setup.b, core::framePixelSize(setup.frame)));
    setup.frame = core::frameAlongAxis(setup.frame, axis, bounds);
  }
  core::PairRequest& request = run.request;
  request.frame = setup.frame;
  request.mor = o.mor;
  request.contact = o.contact;
  request.boxTest = o.boxTest;
  request.normal = o.normal;
  const std::unique_ptr<raster::DepthStencilDevice> device =
      makeDevice(setup.frame.width, setup.frame.height);
  std::optional<std::array<int, 2>> pixel;
  if (!o.pixel.empty()) {
    const auto [x, y] = parsePixel(o.pixel, setup.frame);
    pixel = std::array<int, 2>{x, y};
    if (!setup.layered())
      run.probe.emplace(x, y);
  }
  TwoObservers observers(run.probe ? &*run.probe : nullptr, observer);
  // Each block with its triangle hierarchy, as a run's leaves have theirs: the pair's time
  // (timing_us) then follows what the MOR covers; building them is not part of it.
  const core::PairBlock a = core::PairBlock::withHierarchy(setup.a);
  const core::PairBlock b = core::PairBlock::withHierarchy(setup.b);
  if (setup.layered()) {
    run.layered = pixel ? core::collideLayered(*device, a, b, request, *pixel)
                        : core::collideLayered(*device, a, b, request);
    return run;
  }
  run.result =
      core::collidePair(*device, a, b, request, run.probe || observer ? &observers : nullptr);
  if (o.mode != core::PairMode::Reference)
    run.modeReport = modeJson(o.mode, *device, setup, request, a, b, run.result);
  return run;
}

nlohmann::ordered_json pairRunJson(const PairRun& run, bool noTiming) {
  nlohmann::ordered_json j = run.layered ? layeredResultToJson(run.setup, run.request, *run.layered)
                                         : pairResultToJson(run.setup, run.request, run.result);
  if (run.modeReport)
    j["mode"] = *run.modeReport;
  if (run.axisRule != core::ViewAxisRule::Scene) {
    j["view_axis_rule"] = core::toString(run.axisRule);
    j["view_axis"] = core::toString(run.setup.frame.axis);
  }
  if (noTiming)
    output::removeTimingFields(j);
  if (run.probe)
    j["pixel"] = run.probe->toJson(run.result);
  return j;
}

void printPairRun(std::ostream& out, const PairRun& run, bool picture) {
  if (run.axisRule != core::ViewAxisRule::Scene)
    out << "view axis " << core::toString(run.setup.frame.axis) << " (rule "
        << core::toString(run.axisRule) << ")\n";
  if (run.layered)
    printLayeredReport(out, run.setup, run.request, *run.layered, picture);
  else
    printPairReport(out, run.setup, run.request, run.result, picture);
  if (run.modeReport)
    printMode(out, *run.modeReport);
}

}  // namespace recode::explain
