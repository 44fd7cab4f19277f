#include "pair/layered_report.hpp"

#include <algorithm>
#include <iomanip>
#include <string>
#include <vector>

#include "pair/pair_report.hpp"
#include "recode/io/printable.hpp"

namespace recode::explain {

namespace {

using nlohmann::ordered_json;

const char* kindOf(bool closed) {
  return closed ? "closed mesh" : "convex block";
}

// At most 72 x 30 characters: '#' where some pixel of the cell overlaps (length > 0), '+' where
// the meshes only touch, '.' elsewhere.
void printOverlapPicture(std::ostream& out, const core::LayeredPairResult& r) {
  const raster::PixelRect& m = r.mor;
  const int cols = std::min(m.width(), 72), rows = std::min(m.height(), 30);
  out << "  interference in the MOR, top row first ('#' overlap, '+' touching, '.' none):\n";
  for (int row = rows - 1; row >= 0; --row) {
    std::string line = "    ";
    const int y0 = row * m.height() / rows, y1 = (row + 1) * m.height() / rows;
    for (int col = 0; col < cols; ++col) {
      const int x0 = col * m.width() / cols, x1 = (col + 1) * m.width() / cols;
      char shown = '.';
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          if (r.overlapSteps.at(m.x0 + x, m.y0 + y) > 0)
            shown = '#';
          else if (r.interferes.at(m.x0 + x, m.y0 + y) != 0 && shown == '.')
            shown = '+';
        }
      line += shown;
    }
    out << line << "\n";
  }
}

ordered_json intervalsJson(const std::vector<core::DepthInterval>& intervals) {
  ordered_json list = ordered_json::array();
  for (const core::DepthInterval& d : intervals)
    list.push_back(ordered_json::array({d.min, d.max}));
  return list;
}

// The probed pixel (`--pixel`): each mesh's entries and exits in depth order, the intervals the
// sweep pairs them into, and the depths inside both.
ordered_json layeredPixelJson(const core::LayeredPixel& p) {
  ordered_json j;
  j["x"] = p.x;
  j["y"] = p.y;
  j["in_mor"] = p.inMor;
  j["entries_a"] = p.entriesA;
  j["exits_a"] = p.exitsA;
  j["entries_b"] = p.entriesB;
  j["exits_b"] = p.exitsB;
  j["inside_a"] = intervalsJson(p.insideA);
  j["inside_b"] = intervalsJson(p.insideB);
  j["inside_both"] = intervalsJson(p.insideBoth);
  j["interferes"] = !p.insideBoth.empty();
  return j;
}

}  // namespace

ordered_json layeredResultToJson(const PairSetup& setup, const core::PairRequest& request,
                                 const core::LayeredPairResult& r) {
  ordered_json j;
  j["method"] = "layered";
  j["collide"] = r.collide;
  j["mor"] = pixelRectJson(r.mor);
  j["interfering_pixels"] = r.interferingPixels;
  j["overlap_volume"] = r.overlapVolume;
  j["containment"] = core::toString(r.containment);
  j["layers"] = ordered_json::array({r.layersA, r.layersB});
  j["passes"] = r.passes;
  j["contact"] = contactRegionJson(r.contact);
  j["timing_us"] = r.timing.totalUs;
  ordered_json steps;
  for (int s = 0; s < core::kLayerStepCount; ++s)
    steps[std::string(core::toString(static_cast<core::LayerStep>(s)))] =
        r.timing.stepUs[static_cast<std::size_t>(s)];
  j["timing_steps_us"] = steps;
  addRunKeys(j, setup, request, r);
  j["closed"] = ordered_json::array({setup.closedA, setup.closedB});
  j["source"] = setup.source;
  if (r.pixel)
    j["pixel"] = layeredPixelJson(*r.pixel);
  return j;
}

void printLayeredReport(std::ostream& out, const PairSetup& setup, const core::PairRequest& request,
                        const core::LayeredPairResult& r, bool picture) {
  const core::FrameSpec& f = setup.frame;
  out << "RECODE pair, layered: " << io::printable(setup.nameA) << " (A, " << kindOf(setup.closedA)
      << ", " << setup.a.triangleCount() << " triangles) and " << io::printable(setup.nameB)
      << " (B, " << kindOf(setup.closedB) << ", " << setup.b.triangleCount() << " triangles) from "
      << io::printable(setup.source) << "\n  view along " << core::toString(f.axis) << ", "
      << f.width << "x" << f.height << " pixels over [" << f.window.umin << ", " << f.window.vmin
      << "] - [" << f.window.umax << ", " << f.window.vmax << "], MOR "
      << core::toString(request.mor) << "\n";
  if (r.mor.empty()) {
    out << "  the boxes do not overlap: no pass drawn, no pixel read\n"
        << "  verdict: no collision\n";
    return;
  }
  out << "  MOR [" << r.mor.x0 << ", " << r.mor.y0 << ") - [" << r.mor.x1 << ", " << r.mor.y1
      << "): layers A " << r.layersA << ", B " << r.layersB << "; " << r.passes << " passes, "
      << r.stencilPixelsRead << " stencil and " << r.depthPixelsRead << " depth pixels read\n";
  if (!r.collide) {
    out << "  verdict: no collision\n";
  } else {
    out << "  verdict: COLLIDE, " << r.interferingPixels << " interfering pixels, overlap volume "
        << r.overlapVolume << " (world units^3)\n";
    out << "  contact region: area " << r.contact.area << " (world units^2)";
    if (!r.contact.box.isEmpty()) {
      const auto& lo = r.contact.box.min;
      const auto& hi = r.contact.box.max;
      out << ", box (" << lo.x() << ", " << lo.y() << ", " << lo.z() << ") - (" << hi.x() << ", "
          << hi.y() << ", " << hi.z() << "), longest overlap " << r.contact.maxDepth;
    }
    out << "\n";
    if (r.contact.normal) {
      const Eigen::Vector3d& n = r.contact.normal->normal;
      out << "  contact normal (A towards B): (" << n.x() << ", " << n.y() << ", " << n.z()
          << "), penetration depth " << r.contact.normal->depth << "\n";
    }
  }
  if (r.containment != core::Containment::None)
    out << "  containment: "
        << (r.containment == core::Containment::AInsideB   ? "A lies inside B"
            : r.containment == core::Containment::BInsideA ? "B lies inside A"
                                                           : "A and B fill the same depths")
        << "\n";
  out << "  time " << std::fixed << std::setprecision(0) << r.timing.totalUs << " us:";
  for (int s = 0; s < core::kLayerStepCount; ++s)
    out << " " << core::toString(static_cast<core::LayerStep>(s)) << " "
        << r.timing.stepUs[static_cast<std::size_t>(s)];
  out << "\n" << std::defaultfloat;
  if (picture)
    printOverlapPicture(out, r);
}

}  // namespace recode::explain
