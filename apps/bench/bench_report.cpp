// The bench's CSV and Markdown summary.
#include "bench/bench_report.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <thread>

namespace recode::app {

namespace {

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

// 1234567 -> "1,234,567", as the docs write counts. Built forwards, digit by digit (g++ 12
// warns falsely about std::string::insert here).
std::string grouped(long long value) {
  const std::string digits = std::to_string(value < 0 ? -value : value);
  std::string out = value < 0 ? "-" : "";
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0)
      out += ',';
    out += digits[i];
  }
  return out;
}

// Three significant digits for times that span microseconds to seconds.
std::string milliseconds(double ms) {
  if (ms >= 100.0)
    return fixed(ms, 0);
  if (ms >= 10.0)
    return fixed(ms, 1);
  if (ms >= 1.0)
    return fixed(ms, 2);
  return fixed(ms, 3);
}

std::vector<const BenchRow*> rowsOf(const std::vector<BenchRow>& rows,
                                    const std::string& experiment, const std::string& scene) {
  std::vector<const BenchRow*> out;
  for (const BenchRow& r : rows)
    if (r.experiment == experiment && r.scene == scene)
      out.push_back(&r);
  return out;
}

// Algorithms in the order they first appear (the judge first).
std::vector<std::string> algorithmsOf(const std::vector<const BenchRow*>& rows) {
  std::vector<std::string> names;
  for (const BenchRow* r : rows)
    if (std::find(names.begin(), names.end(), r->algorithm) == names.end())
      names.push_back(r->algorithm);
  return names;
}

std::vector<int> levelsOf(const std::vector<const BenchRow*>& rows) {
  std::set<int> levels;
  for (const BenchRow* r : rows)
    levels.insert(r->trianglesPerBlock);
  return {levels.begin(), levels.end()};
}

const BenchRow* find(const std::vector<const BenchRow*>& rows, int level,
                     const std::string& algorithm) {
  for (const BenchRow* r : rows)
    if (r->trianglesPerBlock == level && r->algorithm == algorithm)
      return r;
  return nullptr;
}

void writeTable1(std::ostream& out, const std::vector<const BenchRow*>& rows) {
  out << "| MOR | triangles | frames | collision time, s | mean, ms | sd, ms | box tests | pair "
         "tests | stencil px read | depth px read | contacts | missed | extra |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const BenchRow* min = nullptr;
  const BenchRow* full = nullptr;
  for (const BenchRow* r : rows) {
    if (!r->recode)
      continue;
    out << "| " << r->algorithm << " | " << grouped(r->triangles) << " | " << r->frames << " | "
        << fixed(r->totalMs / 1000.0, 3) << " | " << milliseconds(r->meanMs) << " | "
        << milliseconds(r->sdMs) << " | " << grouped(r->recode->boxTests) << " | "
        << grouped(r->recode->pairTests) << " | " << grouped(r->recode->stencilPixelsRead) << " | "
        << grouped(r->recode->depthPixelsRead) << " | " << grouped(r->contacts) << " | "
        << r->score.missed << " | " << r->score.extra << " |\n";
    if (r->algorithm == "recode-min")
      min = r;
    if (r->algorithm == "recode-full-screen")
      full = r;
  }
  if (min && full && min->totalMs > 0.0 && min->recode->stencilPixelsRead > 0) {
    out << "\nFULL/MIN (FULL = the whole screen per pair test, as in the paper): collision time "
        << fixed(full->totalMs / min->totalMs, 1) << " : 1, stencil pixels read "
        << fixed(static_cast<double>(full->recode->stencilPixelsRead) /
                     static_cast<double>(min->recode->stencilPixelsRead),
                 1)
        << " : 1 (the paper: 472 s : 3.1 s, about 152 : 1).\n";
  }
}

// A table with a row per tessellation level (its triangles first) and a column per algorithm,
// each cell written by `cell` for the row of that level and algorithm (null where none ran).
void writeLevelTable(std::ostream& out, const std::vector<const BenchRow*>& rows,
                     const std::vector<std::string>& algorithms,
                     const std::function<std::string(const BenchRow*)>& cell) {
  out << "| triangles |";
  for (const std::string& a : algorithms)
    out << ' ' << a << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < algorithms.size(); ++i)
    out << "---|";
  out << '\n';
  for (int level : levelsOf(rows)) {
    const BenchRow* any = algorithms.empty() ? nullptr : find(rows, level, algorithms.front());
    out << "| " << grouped(any ? any->triangles : 0) << " |";
    for (const std::string& a : algorithms)
      out << ' ' << cell(find(rows, level, a)) << " |";
    out << '\n';
  }
}

void writeTimeTable(std::ostream& out, const std::vector<const BenchRow*>& rows) {
  writeLevelTable(out, rows, algorithmsOf(rows), [](const BenchRow* r) {
    return r ? milliseconds(r->meanMs) + " (" + milliseconds(r->sdMs) + ")" : std::string();
  });
}

// The layered algorithms' passes per pose and layers (the closed-mesh experiment).
void writeLayersTable(std::ostream& out, const std::vector<const BenchRow*>& rows) {
  std::vector<std::string> algorithms;
  for (const std::string& a : algorithmsOf(rows))
    for (const BenchRow* r : rows)
      if (r->algorithm == a && r->layered) {
        algorithms.push_back(a);
        break;
      }
  writeLevelTable(out, rows, algorithms, [](const BenchRow* r) {
    if (!r || !r->layered || r->frames <= 0)
      return std::string();
    return fixed(static_cast<double>(r->layered->passes) / r->frames, 1) + " passes, layers " +
           std::to_string(r->layered->layersA) + " / " + std::to_string(r->layered->layersB);
  });
}

void writeAccuracyTable(std::ostream& out, const std::vector<const BenchRow*>& rows) {
  std::vector<std::string> algorithms = algorithmsOf(rows);
  algorithms.erase(algorithms.begin());  // the judge agrees with itself
  out << "| triangles | judged frames | true contacts |";
  for (const std::string& a : algorithms)
    out << ' ' << a << " |";
  out << "\n|---|---|---|";
  for (std::size_t i = 0; i < algorithms.size(); ++i)
    out << "---|";
  out << '\n';
  for (int level : levelsOf(rows)) {
    const BenchRow* judge = find(rows, level, "cgal");
    out << "| " << grouped(judge ? judge->triangles : 0) << " | "
        << (judge ? std::to_string(judge->judgedFrames) : "") << " | "
        << (judge ? grouped(judge->score.truth) : "") << " |";
    for (const std::string& a : algorithms) {
      const BenchRow* r = find(rows, level, a);
      out << ' '
          << (r ? grouped(r->score.found) + " (" + std::to_string(r->score.missed) + " / " +
                      std::to_string(r->score.extra) +
                      (r->seenFiner ? "; " + std::to_string(*r->seenFiner) + " finer" : "") + ")"
                : "")
          << " |";
    }
    out << '\n';
  }
}

}  // namespace

namespace {

// The host's own share of a RECODE frame: the frame minus the wait for the device (the pair
// layer, the devices' set-up and recording, the use of what came back).
double hostMsPerFrame(const BenchRow& r) {
  const double wait = r.recode->deviceWaitUs / 1000.0 / static_cast<double>(r.frames);
  return std::max(0.0, r.meanMs - wait);
}

}  // namespace

void writeBenchCsv(std::ostream& out, const std::vector<BenchRow>& rows) {
  out << "experiment,scene,triangles_per_block,triangles,algorithm,frames,judged_frames,"
         "total_ms,mean_ms,sd_ms,contacts,truth,found_judged,missed,extra,box_tests,pair_tests,"
         "stencil_pixels_read,depth_pixels_read,seen_finer,submissions_per_frame,"
         "readback_bytes_per_frame,device_wait_ms_per_frame,host_ms_per_frame,dispatches_per_frame";
  for (const char* name : raster::TransferCounters::kStageNames)
    out << ",stage_ms_" << name;
  out << ",passes_per_frame,layers_a,layers_b\n";
  for (const BenchRow& r : rows) {
    out << r.experiment << ',' << r.scene << ',' << r.trianglesPerBlock << ',' << r.triangles << ','
        << r.algorithm << ',' << r.frames << ',' << r.judgedFrames << ',' << fixed(r.totalMs, 4)
        << ',' << fixed(r.meanMs, 4) << ',' << fixed(r.sdMs, 4) << ',' << r.contacts << ','
        << r.score.truth << ',' << r.score.found << ',' << r.score.missed << ',' << r.score.extra
        << ',';
    if (r.recode)
      out << r.recode->boxTests << ',' << r.recode->pairTests << ',' << r.recode->stencilPixelsRead
          << ',' << r.recode->depthPixelsRead;
    else
      out << ",,,";
    out << ',';
    if (r.seenFiner)
      out << *r.seenFiner;
    out << ',';
    if (r.recode && r.frames > 0) {
      const double frames = r.frames;
      out << fixed(static_cast<double>(r.recode->submissions) / frames, 2) << ','
          << fixed(static_cast<double>(r.recode->readbackBytes) / frames, 1) << ','
          << fixed(r.recode->deviceWaitUs / 1000.0 / frames, 4) << ','
          << fixed(hostMsPerFrame(r), 4) << ','
          << fixed(static_cast<double>(r.recode->dispatches) / frames, 2);
      for (const double us : r.recode->stageUs)
        out << ',' << fixed(us / 1000.0 / frames, 4);
    } else {
      out << ",,,,";
      for (std::size_t k = 0; k < raster::TransferCounters::kStages; ++k)
        out << ',';
    }
    out << ',';
    if (r.layered && r.frames > 0)
      out << fixed(static_cast<double>(r.layered->passes) / r.frames, 2) << ','
          << r.layered->layersA << ',' << r.layered->layersB;
    else
      out << ",,";
    out << '\n';
  }
}

void writeBenchSummary(std::ostream& out, const std::vector<const Experiment*>& experiments,
                       const std::vector<BenchRow>& rows, const BenchContext& context) {
  out << "# recode bench" << (context.quick ? " (--quick)" : "") << "\n\n"
      << "- command: `" << context.command << "`\n"
      << "- machine: " << context.machine << "\n"
      << "- compiler: " << context.compiler << "\n"
      << "- threads: recode-cpu's pair tests on " << context.recodeThreads
      << " (--threads); the other RECODE devices draw from one (llvmpipe and lavapipe "
         "rasterize on threads of their own); FCL, Bullet and the CGAL judge run on one\n"
      << "- times: collision time per frame as each library's user pays it "
         "(docs/benchmarks.md); missed / extra: colliding leaf pairs against CGAL's exact "
         "answer on the judged frames\n";
  for (const Experiment* e : experiments) {
    out << "\n## " << e->title << " (`" << e->name << "`)\n";
    for (const std::string& scene : e->scenes) {
      const std::vector<const BenchRow*> sceneRows = rowsOf(rows, e->name, scene);
      if (sceneRows.empty())
        continue;
      out << "\n### " << scene << "\n\n";
      if (e->name == "table1") {
        writeTable1(out, sceneRows);
        out << "\nMissed / extra against CGAL over " << sceneRows.front()->judgedFrames
            << " judged frames with " << sceneRows.front()->score.truth << " true contacts.\n";
        continue;
      }
      out << "Mean collision time per frame, ms (standard deviation):\n\n";
      writeTimeTable(out, sceneRows);
      out << "\nColliding pairs found on the judged frames (missed / extra against CGAL; for "
             "recode-adaptive also the pairs recode-cpu missed that it saw at finer pixels):\n\n";
      writeAccuracyTable(out, sceneRows);
      if (e->closedMeshes) {
        out << "\nThe layered pair's passes per pose and most layers of each mesh at a pixel:\n\n";
        writeLayersTable(out, sceneRows);
      }
    }
  }
}

std::string describeMachine() {
  std::string model = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos)
        model = line.substr(line.find_first_not_of(' ', colon + 1));
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

}  // namespace recode::app
