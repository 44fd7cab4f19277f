// gnuplot data, scripts and PNGs for the bench.
#include "bench/bench_plots.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <sstream>
#include <stdexcept>

#include "output/atomic_file.hpp"

extern char** environ;

namespace recode::app {

namespace {

// A path inside a gnuplot single-quoted string, where '' stands for one quote.
std::string quoted(const std::filesystem::path& path) {
  std::string s;
  for (char c : path.string())
    s += c == '\'' ? std::string("''") : std::string(1, c);
  return "'" + s + "'";
}

// Runs `gnuplot script`; returns "" on success, else what went wrong.
std::string runGnuplot(const std::filesystem::path& script) {
  const std::string path = script.string();
  char program[] = "gnuplot";
  std::vector<char> arg(path.begin(), path.end());
  arg.push_back('\0');
  char* argv[] = {program, arg.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", nullptr, nullptr, argv, environ);
  if (spawned == ENOENT)
    return "gnuplot was not found (Debian: apt-get install gnuplot-nox)";
  if (spawned != 0)
    return std::string("gnuplot could not be started: ") + std::strerror(spawned);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR)
      return std::string("waiting for gnuplot failed: ") + std::strerror(errno);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return "gnuplot failed on " + path;
  return "";
}

struct Series {
  std::string algorithm;
  std::vector<const BenchRow*> points;  // by triangles
};

std::vector<Series> seriesOf(const std::vector<BenchRow>& rows, const std::string& experiment,
                             const std::string& scene) {
  std::vector<Series> series;
  for (const BenchRow& r : rows) {
    if (r.experiment != experiment || r.scene != scene || r.algorithm == "cgal")
      continue;
    auto it = std::find_if(series.begin(), series.end(),
                           [&](const Series& s) { return s.algorithm == r.algorithm; });
    if (it == series.end()) {
      series.push_back({r.algorithm, {}});
      it = series.end() - 1;
    }
    it->points.push_back(&r);
  }
  for (Series& s : series)
    std::sort(s.points.begin(), s.points.end(),
              [](const BenchRow* a, const BenchRow* b) { return a->triangles < b->triangles; });
  return series;
}

void writeScript(std::ostream& gp, const std::filesystem::path& dat,
                 const std::filesystem::path& png, const std::string& title,
                 const std::vector<Series>& series) {
  long long lo = -1, hi = -1;
  for (const Series& s : series)
    for (const BenchRow* r : s.points) {
      lo = lo < 0 ? r->triangles : std::min(lo, r->triangles);
      hi = std::max(hi, r->triangles);
    }
  gp << "set terminal pngcairo size 1200,480 font ',10'\n"
     << "set output " << quoted(png) << "\n"
     << "set multiplot layout 1,2 title '" << title << "'\n"
     << "set logscale xy\nset grid\nset key top left\n"
     << "set xlabel 'triangles in the scene'\n";
  // A single tessellation level (--quick) still gets a readable axis around it.
  gp << "set xrange [" << static_cast<double>(lo) / 2.0 << ":" << static_cast<double>(hi) * 2.0
     << "]\n";
  for (int column : {2, 3}) {
    gp << "set ylabel '" << (column == 2 ? "mean" : "standard deviation of")
       << " collision time per frame, ms'\n";
    gp << "plot ";
    for (std::size_t i = 0; i < series.size(); ++i)
      gp << (i ? ", " : "") << quoted(dat) << " index " << i << " using 1:" << column
         << " with linespoints title '" << series[i].algorithm << "'";
    gp << '\n';
  }
  gp << "unset multiplot\n";
}

}  // namespace

PlotOutcome writeBenchPlots(const std::filesystem::path& dir,
                            const std::vector<const Experiment*>& experiments,
                            const std::vector<BenchRow>& rows) {
  PlotOutcome outcome;
  const std::filesystem::path plots = dir / "plots";
  std::filesystem::create_directories(plots);
  for (const Experiment* e : experiments) {
    if (e->name == "table1")
      continue;
    for (const std::string& scene : e->scenes) {
      const std::vector<Series> series = seriesOf(rows, e->name, scene);
      if (series.empty())
        continue;
      // "comb-rotate-aligned", "random-cones", "table2-hand-grasp", "figure8-random-shapes".
      const std::string id = scene.rfind(e->name, 0) == 0 ? scene : e->name + "-" + scene;
      const std::filesystem::path dat = plots / (id + ".dat");
      const std::filesystem::path gp = plots / (id + ".gp");
      const std::filesystem::path png = dir / (id + ".png");
      {
        std::ostringstream data;
        data << "# triangles mean_ms sd_ms; one block per algorithm\n";
        for (const Series& s : series) {
          data << "# " << s.algorithm << '\n';
          for (const BenchRow* r : s.points)
            data << r->triangles << ' ' << r->meanMs << ' ' << r->sdMs << '\n';
          data << "\n\n";
        }
        std::ostringstream script;
        writeScript(script, dat, png, id == scene ? scene : scene + " (" + e->name + ")", series);
        output::writeFileAtomically(dat, data.str());
        output::writeFileAtomically(gp, script.str());
      }
      outcome.scripts.push_back(gp);
      if (!outcome.problem.empty())
        continue;  // gnuplot already failed: keep writing the scripts, draw nothing
      outcome.problem = runGnuplot(gp);
      if (outcome.problem.empty())
        outcome.pngs.push_back(png);
    }
  }
  return outcome;
}

}  // namespace recode::app
