#include "pair/pair_report.hpp"

#include <iomanip>
#include <string>

#include "recode/io/printable.hpp"

namespace recode::explain {

namespace {

using nlohmann::ordered_json;

ordered_json vec(const Eigen::Vector3d& v) {
  return ordered_json::array({v.x(), v.y(), v.z()});
}

// One character per case for the text picture: the case's digit 0-8, so that every case can
// be told apart (1 A only, 2 B behind A, 7 B in front of A, 8 B only).
char caseGlyph(int c) {
  if (c < 0)
    return ' ';
  return static_cast<char>('0' + c);
}

// Which case a cell of several pixels shows: interference first, then the others by how
// informative they are.
int cellPriority(int c) {
  static constexpr int kPriority[] = {0, 2, 3, 9, 9, 9, 9, 3, 1};
  return kPriority[c];
}

void printCaseCounts(std::ostream& out, const core::PairResult& r) {
  out << "  MOR [" << r.mor.x0 << ", " << r.mor.y0 << ") - [" << r.mor.x1 << ", " << r.mor.y1
      << "): " << r.stencilPixelsRead << " stencil pixels read\n"
      << "  cases inside the MOR:\n";
  for (int c = 0; c < core::kCaseCount; ++c)
    out << "    " << c << "  " << std::left << std::setw(26) << core::caseName(c) << std::right
        << std::setw(9) << r.caseCounts[static_cast<std::size_t>(c)] << " px"
        << (core::isInterfering(c) ? "  interference" : "") << "\n";
}

void printVerdict(std::ostream& out, const core::PairResult& r) {
  if (!r.collide) {
    out << "  verdict: no collision\n";
    return;
  }
  out << "  verdict: COLLIDE, " << r.interferingPixels << " interfering pixels\n"
      << "  contact region: area " << r.contact.area << " (world units^2)";
  if (!r.contact.box.isEmpty()) {
    const auto& lo = r.contact.box.min;
    const auto& hi = r.contact.box.max;
    out << ", box (" << lo.x() << ", " << lo.y() << ", " << lo.z() << ") - (" << hi.x() << ", "
        << hi.y() << ", " << hi.z() << "), greatest overlap depth " << r.contact.maxDepth << ", "
        << r.depthPixelsRead << " depth pixels read";
  }
  out << "\n";
  if (r.contact.normal) {
    const Eigen::Vector3d& n = r.contact.normal->normal;
    out << "  contact normal (A towards B): (" << n.x() << ", " << n.y() << ", " << n.z()
        << "), penetration depth " << r.contact.normal->depth << "\n";
  }
}

void printTiming(std::ostream& out, const core::PairResult& r) {
  out << "  time " << std::fixed << std::setprecision(0) << r.timing.totalUs << " us:";
  for (int s = 0; s < core::kPairStepCount; ++s) {
    const double us = r.timing.stepUs[static_cast<std::size_t>(s)];
    if (us > 0.0)
      out << " " << core::toString(static_cast<core::PairStep>(s)) << " " << us;
  }
  out << " classify " << r.timing.classifyUs << "\n" << std::defaultfloat;
}

// At most 72 x 30 characters, each cell the most telling case among its pixels.
void printCasePicture(std::ostream& out, const core::PairResult& r) {
  const int cols = std::min(r.mor.width(), 72), rows = std::min(r.mor.height(), 30);
  out << "  cases in the MOR, top row first (the case's digit 0-8, '3'-'6' "
         "interference):\n";
  for (int row = rows - 1; row >= 0; --row) {
    std::string line = "    ";
    const int y0 = row * r.mor.height() / rows, y1 = (row + 1) * r.mor.height() / rows;
    for (int col = 0; col < cols; ++col) {
      const int x0 = col * r.mor.width() / cols, x1 = (col + 1) * r.mor.width() / cols;
      int shown = 0;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          const int c = r.caseMap.at(r.mor.x0 + x, r.mor.y0 + y);
          if (cellPriority(c) > cellPriority(shown))
            shown = c;
        }
      line += caseGlyph(shown);
    }
    out << line << "\n";
  }
}

}  // namespace

ordered_json pixelRectJson(const raster::PixelRect& r) {
  return ordered_json::array({r.x0, r.y0, r.x1, r.y1});
}

ordered_json contactRegionJson(const core::ContactRegion& c) {
  ordered_json contact;
  ordered_json points = ordered_json::array();
  for (const Eigen::Vector3d& p : c.points)
    points.push_back(vec(p));
  contact["points"] = points;
  contact["box"] = c.box.isEmpty() ? ordered_json(nullptr)
                                   : ordered_json::array({vec(c.box.min), vec(c.box.max)});
  contact["area"] = c.area;
  contact["max_depth"] = c.maxDepth;
  contact["pixels"] = c.pixels;
  contact["collapsed_pixels"] = c.collapsedPixels;
  if (c.normal) {  // only with --normal, so the default report keeps its bytes
    contact["normal"] = vec(c.normal->normal);
    contact["penetration_depth"] = c.normal->depth;
  }
  return contact;
}

ordered_json frameJson(const core::FrameSpec& f, double depthMin, double depthMax) {
  ordered_json frame;
  frame["axis"] = core::toString(f.axis);
  const core::ViewWindow& w = f.window;
  frame["window"] = ordered_json::array({w.umin, w.vmin, w.umax, w.vmax});
  frame["resolution"] = ordered_json::array({f.width, f.height});
  frame["depth_range"] = ordered_json::array({depthMin, depthMax});
  return frame;
}

ordered_json pairResultToJson(const PairSetup& setup, const core::PairRequest& request,
                              const core::PairResult& r) {
  ordered_json j;
  j["collide"] = r.collide;
  j["mor"] = pixelRectJson(r.mor);
  ordered_json counts = ordered_json::object();
  for (int c = 0; c < core::kCaseCount; ++c)
    counts[std::to_string(c)] = r.caseCounts[static_cast<std::size_t>(c)];
  j["case_counts"] = counts;
  j["interfering_pixels"] = r.interferingPixels;
  j["contact"] = contactRegionJson(r.contact);
  j["timing_us"] = r.timing.totalUs;
  ordered_json steps;
  for (int s = 0; s < core::kPairStepCount; ++s)
    steps[std::string(core::toString(static_cast<core::PairStep>(s)))] =
        r.timing.stepUs[static_cast<std::size_t>(s)];
  steps["classify"] = r.timing.classifyUs;
  j["timing_steps_us"] = steps;
  addRunKeys(j, setup, request, r);
  j["source"] = setup.source;
  return j;
}

void printPairReport(std::ostream& out, const PairSetup& setup, const core::PairRequest& request,
                     const core::PairResult& r, bool picture) {
  const core::FrameSpec& f = setup.frame;
  // Names and the file come from the user: echoed with control characters escaped.
  out << "RECODE pair: " << io::printable(setup.nameA) << " (A, " << setup.a.triangleCount()
      << " triangles) and " << io::printable(setup.nameB) << " (B, " << setup.b.triangleCount()
      << " triangles) from " << io::printable(setup.source) << "\n  view along "
      << core::toString(f.axis) << ", " << f.width << "x" << f.height << " pixels over ["
      << f.window.umin << ", " << f.window.vmin << "] - [" << f.window.umax << ", " << f.window.vmax
      << "], MOR " << core::toString(request.mor) << "\n";
  if (r.mor.empty()) {
    out << "  the boxes do not overlap: no pass drawn, no pixel read\n"
        << "  verdict: no collision\n";
    return;
  }
  printCaseCounts(out, r);
  printVerdict(out, r);
  printTiming(out, r);
  if (picture)
    printCasePicture(out, r);
}

void PixelProbe::afterStep(core::PairStep step, raster::DepthStencilDevice& device) {
  const raster::PixelRect one{x_, y_, x_ + 1, y_ + 1};
  steps_[std::string(core::toString(step))] = {{"depth", device.readDepth(one).at(0)},
                                               {"stencil", device.readStencil(one).at(0)}};
}

ordered_json PixelProbe::toJson(const core::PairResult& r) const {
  ordered_json j;
  j["x"] = x_;
  j["y"] = y_;
  const bool inMor = x_ >= r.mor.x0 && x_ < r.mor.x1 && y_ >= r.mor.y0 && y_ < r.mor.y1;
  j["case"] = inMor ? ordered_json(int{r.caseMap.at(x_, y_)}) : ordered_json(nullptr);
  j["steps"] = steps_;
  return j;
}

std::vector<std::uint8_t> frameCaseImage(const core::FrameSpec& frame, const core::PairResult& r) {
  raster::PixelBuffer<std::uint8_t> image({0, 0, frame.width, frame.height}, std::uint8_t{255});
  for (int y = r.mor.y0; y < r.mor.y1; ++y)
    for (int x = r.mor.x0; x < r.mor.x1; ++x)
      image.at(x, y) = r.caseMap.at(x, y);
  return std::move(image.data);
}

}  // namespace recode::explain
