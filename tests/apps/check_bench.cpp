// Checks what `recode bench --quick` wrote, against docs/benchmarks.md and against
// facts derived independently of the bench:
// - bench.csv has the documented header and exactly one row per experiment, scene and
//   algorithm (the expected lists are written here from the experiment definitions in
//   docs/benchmarks.md, not read from the bench);
// - frames and triangles agree with the built-in scene itself (core, not the bench);
// - every algorithm's counts add up against the ground truth: found - extra + missed == truth,
//   the same truth for every algorithm of a case, and the judge agrees with itself;
// - times are consistent (total = mean x frames), RECODE's counters are present only for it;
// - MIN, MAX and FULL MORs find the same contacts while reading more and more stencil pixels,
//   and RECODE finds the same pairs on the CPU and the GL device;
// - recode-view-axis tests the same node and leaf pairs as recode-cpu (only the drawing axis
//   of a leaf pair changes);
// - recode-vulkan batches a frame's pair tests into at most 2 submissions, reading back what
//   recode-vulkan-per-pair reads; the CPU device counts no submission;
// - summary.md has the FULL/MIN ratio and every plot is a PNG;
// - the closed-mesh experiment: its rows, the truth its shapes give, the containments the
//   surface-only peers miss and the layered pair finds (checkClosedExperiment).
//
// Usage: recode_check_bench DIR

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "recode/pair/frame.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/simulation.hpp"

namespace {

namespace fs = std::filesystem;

int failures = 0;

void fail(const std::string& message) {
  std::cerr << "FAIL: " << message << '\n';
  ++failures;
}

const char* const kHeader =
    "experiment,scene,triangles_per_block,triangles,algorithm,frames,judged_frames,total_ms,"
    "mean_ms,sd_ms,contacts,truth,found_judged,missed,extra,box_tests,pair_tests,"
    "stencil_pixels_read,depth_pixels_read,seen_finer,submissions_per_frame,"
    "readback_bytes_per_frame,device_wait_ms_per_frame,host_ms_per_frame,dispatches_per_frame,"
    "stage_ms_vertex,stage_ms_setup,stage_ms_binning,stage_ms_raster,stage_ms_reads,"
    "passes_per_frame,layers_a,layers_b";

// The compute device's stage columns (a RECODE row's, empty for a peer).
const char* const kStageColumns[] = {"stage_ms_vertex", "stage_ms_setup", "stage_ms_binning",
                                     "stage_ms_raster", "stage_ms_reads"};

struct Row {
  std::map<std::string, std::string> field;
  [[nodiscard]] const std::string& text(const std::string& key) const { return field.at(key); }
  [[nodiscard]] long long count(const std::string& key) const { return std::stoll(text(key)); }
  [[nodiscard]] double number(const std::string& key) const { return std::stod(text(key)); }
  [[nodiscard]] std::string id() const {
    return text("experiment") + "/" + text("scene") + "/" + text("triangles_per_block") + "/" +
           text("algorithm");
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');)
    out.push_back(f);
  if (!line.empty() && line.back() == ',')
    out.emplace_back();
  return out;
}

struct Expected {
  std::string experiment;
  std::vector<std::string> scenes;
  int quickTrianglesPerBlock;
  std::vector<std::string> algorithms;
};

std::vector<Expected> expectations() {
  const std::vector<std::string> all = {"cgal",
                                        "recode-cpu",
                                        "recode-adaptive",
                                        "recode-conservative",
                                        "recode-skip-apart",
                                        "recode-view-axis",
                                        "recode-gl",
                                        "recode-gl-exact",
                                        "recode-vulkan",
                                        "recode-vulkan-per-pair",
                                        "recode-vulkan-speculative",
                                        "recode-vulkan-summaries",
                                        "recode-vulkan-waves",
                                        "recode-vulkan-32",
                                        "recode-vulkan-compute",
                                        "fcl-gjk",
                                        "fcl-obbrss",
                                        "bullet"};
  return {
      {"table1",
       {"hierarchy-9"},
       288,
       {"cgal", "recode-min", "recode-max", "recode-full", "recode-full-screen"}},
      {"table2", {"hand-grasp"}, 56, all},
      {"figure8", {"random-shapes"}, 36, all},
      {"comb",
       {"comb-rotate-aligned", "comb-rotate-offset", "comb-translate-aligned",
        "comb-translate-offset"},
       64,
       all},
      {"random-cones", {"random-cones"}, 16, all},
  };
}

bool isPng(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  return in && std::string(magic, 8) == "\x89PNG\r\n\x1a\n";
}

void checkRow(const Row& r) {
  const std::string id = r.id();
  const long long truth = r.count("truth"), found = r.count("found_judged");
  const long long missed = r.count("missed"), extra = r.count("extra");
  if (found - extra + missed != truth)
    fail(id + ": found - extra + missed = " + std::to_string(found - extra + missed) + ", truth " +
         std::to_string(truth));
  if (missed < 0 || missed > truth || extra < 0 || extra > found)
    fail(id + ": missed or extra out of range");
  if (r.count("contacts") < found)
    fail(id + ": fewer contacts over all frames than on the judged frames");
  const long long frames = r.count("frames"), judged = r.count("judged_frames");
  if (judged != frames)  // --quick scenes are small enough to judge every frame
    fail(id + ": " + std::to_string(judged) + " judged frames of " + std::to_string(frames));
  const double total = r.number("total_ms"), mean = r.number("mean_ms"), sd = r.number("sd_ms");
  if (!(total >= 0.0 && mean >= 0.0 && sd >= 0.0) ||
      std::abs(total - mean * static_cast<double>(frames)) > 1e-3 * static_cast<double>(frames))
    fail(id + ": total " + r.text("total_ms") + " ms is not mean x frames");
  const bool recode = r.text("algorithm").rfind("recode-", 0) == 0;
  // RECODE's own columns: given on its rows, empty on a peer's.
  const auto ownColumn = [&](const char* key) {
    if (r.text(key).empty() == recode)
      fail(id + ": " + key + (recode ? " missing" : " given for a peer"));
  };
  for (const char* key : {"box_tests", "pair_tests", "stencil_pixels_read", "depth_pixels_read",
                          "submissions_per_frame", "readback_bytes_per_frame",
                          "device_wait_ms_per_frame", "host_ms_per_frame", "dispatches_per_frame"})
    ownColumn(key);
  for (const char* key : kStageColumns)
    ownColumn(key);
  // The device's share of the frame: none without a submission, and never more than the frame.
  if (recode) {
    const double wait = r.number("device_wait_ms_per_frame");
    const bool submits = r.number("submissions_per_frame") > 0.0;
    if (!(wait >= 0.0 && wait <= mean + 1e-3) || (wait > 0.0) != submits)
      fail(id + ": device wait " + r.text("device_wait_ms_per_frame") + " ms a frame with " +
           r.text("submissions_per_frame") + " submissions and " + r.text("mean_ms") +
           " ms a frame");
  }
  // The host's share is the rest of the frame (each rounded to 1e-4 ms).
  if (recode) {
    const double host = r.number("host_ms_per_frame");
    const double wait = r.number("device_wait_ms_per_frame");
    if (!(host >= 0.0) || std::abs(host + wait - mean) > 3e-4)
      fail(id + ": host " + r.text("host_ms_per_frame") + " ms + device wait " +
           r.text("device_wait_ms_per_frame") + " ms is not the frame's " + r.text("mean_ms") +
           " ms");
  }
  if (recode && r.count("pair_tests") < r.count("contacts"))
    fail(id + ": more contacts than pair tests");
  if (r.text("algorithm") == "cgal" && (missed != 0 || extra != 0 || found != truth))
    fail(id + ": the judge disagrees with itself");
}

// The row of `id` (experiment/scene/level/algorithm) with checkRow's checks, or null (and a
// failure) when the CSV has none.
const Row* checkedRow(const std::map<std::string, Row>& rows, const std::string& id) {
  const auto it = rows.find(id);
  if (it == rows.end()) {
    fail("bench.csv: no row for " + id);
    return nullptr;
  }
  checkRow(it->second);
  return &it->second;
}

// The closed-mesh experiment (docs/benchmarks.md, "Closed meshes against the peers"), its
// --quick level of 500 triangles a mesh: rows for both paths and every algorithm, 41 poses each.
// On ball-through-torus the truth follows from the shapes: the ball (radius 0.25) centred at
// x = -2 + 0.1 k on the axis of a torus of radius 1 and tube 0.4 meets the solid torus when
// ||x| - 1| <= 0.65, that is 0.4 <= |x| <= 1.6 on these poses (26 of 41; the nearest poses
// clear the tessellated surfaces by more than 0.03), and lies wholly inside the tube when
// ||x| - 1| <= 0.15 (6 poses): those the surface-only peers cannot see, and the layered pair at
// 512 pixels must. Returns the number of rows expected.
std::size_t checkClosedExperiment(const std::map<std::string, Row>& rows, const fs::path& dir) {
  const std::vector<std::string> algorithms = {
      "cgal",       "recode-layered-128", "recode-layered-256", "recode-layered-512",
      "fcl-obbrss", "fcl-obbrss-all",     "bullet-gimpact"};
  std::size_t expected = 0;
  const std::vector<std::string> scenes = {"ball-through-torus", "linked-rings"};
  for (const std::string& scene : scenes) {
    const std::string prefix = "closed/" + scene + "/500/";
    for (const std::string& algorithm : algorithms) {
      ++expected;
      const Row* row = checkedRow(rows, prefix + algorithm);
      if (!row)
        continue;
      const Row& r = *row;
      if (r.count("frames") != 41)
        fail(r.id() + ": " + r.text("frames") + " poses, the path has 41");
      const bool layered = algorithm.rfind("recode-layered-", 0) == 0;
      if (r.text("passes_per_frame").empty() == layered)
        fail(r.id() + ": passes_per_frame " + (layered ? "missing" : "given"));
      if (layered && !(r.number("passes_per_frame") >= 4.0 && r.count("layers_a") >= 1 &&
                       r.count("layers_b") >= 1))
        fail(r.id() + ": fewer than 4 passes or 1 layer a mesh");
      if (scene != "ball-through-torus")
        continue;
      if (r.count("truth") != 26)
        fail(r.id() + ": truth " + r.text("truth") + ", the shapes meet on 26 poses");
      if ((algorithm.rfind("fcl-", 0) == 0 || algorithm == "bullet-gimpact") &&
          r.count("missed") < 6)
        fail(r.id() + ": missed " + r.text("missed") +
             ", fewer than the 6 poses with the ball wholly inside the tube");
      if (algorithm == "recode-layered-512" && (r.count("missed") != 0 || r.count("extra") != 0))
        fail(r.id() + ": missed " + r.text("missed") + ", extra " + r.text("extra"));
    }
    if (!isPng(dir / ("closed-" + scene + ".png")))
      fail((dir / ("closed-" + scene + ".png")).string() + " is missing or not a PNG");
  }
  return expected;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: recode_check_bench DIR\n";
    return 2;
  }
  const fs::path dir(argv[1]);
  std::ifstream csv(dir / "bench.csv");
  std::string line;
  if (!std::getline(csv, line) || line != kHeader) {
    std::cerr << "FAIL: " << (dir / "bench.csv").string() << ": missing or unexpected header\n";
    return 1;
  }
  const std::vector<std::string> keys = split(kHeader);
  std::map<std::string, Row> rows;
  for (int n = 2; std::getline(csv, line); ++n) {
    const std::vector<std::string> values = split(line);
    if (values.size() != keys.size()) {
      fail("bench.csv line " + std::to_string(n) + ": " + std::to_string(values.size()) +
           " fields, expected " + std::to_string(keys.size()));
      continue;
    }
    Row r;
    for (std::size_t i = 0; i < keys.size(); ++i)
      r.field[keys[i]] = values[i];
    if (!rows.emplace(r.id(), r).second)
      fail("bench.csv: two rows for " + r.id());
  }

  std::size_t expectedRows = 0;
  for (const Expected& e : expectations()) {
    for (const std::string& scene : e.scenes) {
      // Frames and triangles of the scene, from core.
      const recode::core::Scene s =
          recode::core::builtinExperimentScene(scene, e.quickTrianglesPerBlock);
      long long triangles = 0;
      recode::core::Aabb bounds;  // at frame 0, for the screen
      for (const recode::core::SceneObject& o : s.objects) {
        const recode::core::ObjectTree tree(o);
        triangles += static_cast<long long>(tree.triangleCount());
        bounds.extend(tree.root().worldAabb);
      }
      const long long frames = s.frames.value_or(recode::core::kDefaultRunFrames);
      const std::string prefix =
          e.experiment + "/" + scene + "/" + std::to_string(e.quickTrianglesPerBlock) + "/";
      long long truth = -1;
      for (const std::string& algorithm : e.algorithms) {
        ++expectedRows;
        const Row* row = checkedRow(rows, prefix + algorithm);
        if (!row)
          continue;
        const Row& r = *row;
        if (r.count("frames") != frames)
          fail(r.id() + ": " + r.text("frames") + " frames, the scene has " +
               std::to_string(frames));
        if (r.count("triangles") != triangles)
          fail(r.id() + ": " + r.text("triangles") + " triangles, the scene has " +
               std::to_string(triangles));
        if (truth < 0)
          truth = r.count("truth");
        else if (r.count("truth") != truth)
          fail(r.id() + ": a different ground truth from the judge's");
      }
      const auto same = [&](const std::string& a, const std::string& b, const char* key) {
        const auto ra = rows.find(prefix + a), rb = rows.find(prefix + b);
        if (ra != rows.end() && rb != rows.end() && ra->second.text(key) != rb->second.text(key))
          fail(prefix + ": " + a + " and " + b + " differ in " + key);
      };
      if (e.experiment == "table1") {
        for (const char* key : {"contacts", "missed", "extra", "pair_tests"}) {
          same("recode-min", "recode-max", key);
          same("recode-min", "recode-full", key);
          same("recode-min", "recode-full-screen", key);
        }
        // The paper's FULL reads the whole screen for every pair test.
        const recode::core::FrameSpec screen =
            recode::core::resolveFrame(s.view, bounds, recode::core::FrameOverrides{});
        const auto fullScreen = rows.find(prefix + "recode-full-screen");
        if (fullScreen != rows.end() &&
            fullScreen->second.count("stencil_pixels_read") !=
                fullScreen->second.count("pair_tests") * screen.width * screen.height)
          fail(prefix + "recode-full-screen: stencil pixels read are not pair tests x " +
               std::to_string(screen.width) + " x " + std::to_string(screen.height));
        const auto stencil = [&](const std::string& a) {
          const auto it = rows.find(prefix + a);
          return it == rows.end() ? -1 : it->second.count("stencil_pixels_read");
        };
        if (!(stencil("recode-min") > 0 && stencil("recode-min") <= stencil("recode-max") &&
              stencil("recode-max") < stencil("recode-full")))
          fail(prefix + ": stencil pixels read do not grow from MIN to MAX to FULL");
      } else {
        // Every device runs the same algorithm on the same frames: the same pairs, and (being
        // exact, or agreeing on coverage) the same pixels read.
        for (const char* key : {"contacts", "missed", "extra", "stencil_pixels_read"})
          for (const char* device :
               {"recode-gl", "recode-gl-exact", "recode-vulkan", "recode-vulkan-per-pair",
                "recode-vulkan-speculative", "recode-vulkan-summaries", "recode-vulkan-waves",
                "recode-vulkan-32", "recode-vulkan-compute"})
            same("recode-cpu", device, key);
        // A frame's pair tests on Vulkan: one submission for the stencil passes of all and one
        // for the contact passes of those that interfere (docs/architecture.md); test by test,
        // up to three each. Both read back the same rectangles.
        same("recode-vulkan", "recode-vulkan-per-pair", "readback_bytes_per_frame");
        const auto vulkan = rows.find(prefix + "recode-vulkan");
        const auto perPair = rows.find(prefix + "recode-vulkan-per-pair");
        // At most `most` bytes read back a pair test (when most > 0) and `submissions` a frame.
        const auto transfersAtMost = [&](const char* name, double most, int submissions) {
          const auto row = rows.find(prefix + name);
          if (row == rows.end())
            return;
          if (row->second.number("submissions_per_frame") > submissions)
            fail(prefix + name + ": " + row->second.text("submissions_per_frame") +
                 " submissions per frame, more than " + std::to_string(submissions));
          const double bytes =
              row->second.number("readback_bytes_per_frame") * row->second.number("frames");
          // (the CSV gives bytes a frame to a tenth)
          if (most > 0.0 &&
              bytes > most * row->second.number("pair_tests") + 0.05 * row->second.number("frames"))
            fail(prefix + name + ": " + row->second.text("readback_bytes_per_frame") +
                 " bytes read back a frame, more than " + std::to_string(static_cast<int>(most)) +
                 " a pair test");
        };
        transfersAtMost("recode-vulkan", 0.0, 2);
        // Speculative contact passes: the stencil and contact passes of every pair in one; with
        // the device's summaries a 64-byte summary a pair test is all that comes back, and the
        // waves only change which device draws a pair.
        transfersAtMost("recode-vulkan-speculative", 0.0, 1);
        transfersAtMost("recode-vulkan-summaries", 64.0, 1);
        transfersAtMost("recode-vulkan-waves", 64.0, 1);
        same("recode-vulkan-summaries", "recode-vulkan-waves", "readback_bytes_per_frame");
        if (vulkan != rows.end() && perPair != rows.end() &&
            perPair->second.number("submissions_per_frame") <
                vulkan->second.number("submissions_per_frame"))
          fail(prefix + "recode-vulkan-per-pair: fewer submissions than the batch");
        // The CPU device hands nothing to hardware.
        const auto cpuRow = rows.find(prefix + "recode-cpu");
        if (cpuRow != rows.end() && (cpuRow->second.number("submissions_per_frame") != 0.0 ||
                                     cpuRow->second.number("readback_bytes_per_frame") != 0.0 ||
                                     cpuRow->second.number("dispatches_per_frame") != 0.0))
          fail(prefix +
               "recode-cpu: submissions, read-back bytes or dispatches counted on the "
               "CPU device");
        // The compute device runs a frame as a fixed set of dispatches (docs/backends.md, "The
        // compute device"): at most 12 a submission, however many draws the frame holds, and
        // its stages' device time (timestamps) within the frame's wait for the device.
        const auto compute = rows.find(prefix + "recode-vulkan-compute");
        if (compute != rows.end()) {
          const Row& c = compute->second;
          if (c.number("dispatches_per_frame") > 12.0 * c.number("submissions_per_frame") + 0.01)
            fail(prefix + "recode-vulkan-compute: " + c.text("dispatches_per_frame") +
                 " dispatches a frame in " + c.text("submissions_per_frame") +
                 " submissions, more than 12 each");
          if (c.number("dispatches_per_frame") <= 0.0)
            fail(prefix + "recode-vulkan-compute: no dispatch counted");
          double stages = 0.0;
          for (const char* key : kStageColumns)
            stages += c.number(key);
          if (!(stages >= 0.0) || stages > c.number("device_wait_ms_per_frame") + 1e-3)
            fail(prefix + "recode-vulkan-compute: its stages took " + std::to_string(stages) +
                 " ms a frame, more than its wait for the device");
        }
        // The view-axis rule only redraws a leaf pair along another axis: the tree descent
        // and the leaf pairs drawn are recode-cpu's.
        for (const char* key : {"box_tests", "pair_tests"})
          same("recode-cpu", "recode-view-axis", key);
        // The skip-apart mode decides every pair as recode-cpu does; it only draws fewer.
        for (const char* key : {"contacts", "missed", "extra", "box_tests", "pair_tests"})
          same("recode-cpu", "recode-skip-apart", key);
        // The modes' promises (docs/algorithm.md, "Beyond the paper"): the conservative mode
        // misses nothing, and the pairs recode-cpu missed that recode-adaptive found are at
        // least those it missed less.
        const auto cpu = rows.find(prefix + "recode-cpu");
        const auto adaptive = rows.find(prefix + "recode-adaptive");
        const auto conservative = rows.find(prefix + "recode-conservative");
        if (conservative != rows.end() && conservative->second.count("missed") != 0)
          fail(prefix + "recode-conservative missed pairs");
        if (cpu != rows.end() && adaptive != rows.end() &&
            adaptive->second.count("seen_finer") <
                cpu->second.count("missed") - adaptive->second.count("missed"))
          fail(prefix + "recode-adaptive: seen_finer below recode-cpu's misses less its own");
        const fs::path png =
            dir /
            ((scene.rfind(e.experiment, 0) == 0 ? scene : e.experiment + "-" + scene) + ".png");
        if (!isPng(png))
          fail(png.string() + " is missing or not a PNG");
      }
    }
  }
  expectedRows += checkClosedExperiment(rows, dir);
  if (rows.size() != expectedRows)
    fail("bench.csv has " + std::to_string(rows.size()) + " rows, expected " +
         std::to_string(expectedRows));

  std::ifstream summaryFile(dir / "summary.md");
  std::stringstream summary;
  summary << summaryFile.rdbuf();
  if (summary.str().find("FULL/MIN (FULL = the whole screen per pair test, as in the paper): "
                         "collision time ") == std::string::npos)
    fail("summary.md has no FULL/MIN ratio");

  if (failures > 0) {
    std::cerr << failures << " problems\n";
    return 1;
  }
  std::cout << "bench output OK: " << rows.size() << " rows, found - extra + missed == truth in "
            << "every row\n";
  return 0;
}
