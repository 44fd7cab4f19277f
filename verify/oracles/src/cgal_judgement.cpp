// RECODE's verdict and contact box against the exact intersection (no CGAL here): the
// tolerance rules of cgal_oracle.hpp and docs/verification.md, "The CGAL oracle". Just over
// 400 lines: the three rules share the judging frame and the view-line probes, and read best
// one after the other.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "recode/pair/pair_cases.hpp"
#include "recode/raster/state.hpp"
#include "recode/verify/cgal_oracle.hpp"
#include "view_line_probe.hpp"

namespace recode::verify {

namespace {

// The pair's frame as the judgement sees it: pixel centres and sizes on the image plane, the
// depth step and the tolerances in world units.
struct JudgeFrame {
  core::OrthoView view;
  double pixelU, pixelV;   // world size of a pixel along u and v
  double edgeU, edgeV;     // kEdgeTolerancePixels in world units along u and v
  double step, tolerance;  // one depth LSB and kDepthToleranceLsb of them, world units

  JudgeFrame(const core::FrameSpec& frame, const core::PairResult& result)
      : view(frame.axis, frame.window, frame.width, frame.height, result.depthMin, result.depthMax),
        pixelU(view.pixelWidth()),
        pixelV(view.pixelHeight()),
        edgeU(kEdgeTolerancePixels * pixelU),
        edgeV(kEdgeTolerancePixels * pixelV),
        step((result.depthMax - result.depthMin) / static_cast<double>(raster::kDepthMax)),
        tolerance(kDepthToleranceLsb * step) {}

  [[nodiscard]] double centreU(int i) const { return view.window().umin + (i + 0.5) * pixelU; }
  [[nodiscard]] double centreV(int j) const { return view.window().vmin + (j + 0.5) * pixelV; }
  [[nodiscard]] double inSteps(double world) const { return world / step; }
};

// The exact box on the image plane and along the axis: (u, v, d) minima and maxima.
struct PlaneBox {
  Eigen::Vector3d min, max;
};

PlaneBox toPlane(const core::OrthoView& view, const core::Aabb& box) {
  // toPlane permutes the coordinates, so it maps a box's corners onto the new box's corners.
  return {view.toPlane(box.min), view.toPlane(box.max)};
}

std::string describe(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Rule (a)'s search: the pixels centred in the exact box's projection, one more each side.
raster::PixelRect missSearchSpan(const ExactIntersection& exact, const JudgeFrame& f) {
  // The extra pixel is against rounding; the test does not depend on the box, which only limits
  // the search. An empty or non-finite box (an inconsistent ExactIntersection) searches it all.
  const bool usable =
      !exact.box.isEmpty() && exact.box.min.allFinite() && exact.box.max.allFinite();
  const PlaneBox box = toPlane(f.view, exact.box);
  const core::ViewWindow& w = f.view.window();
  const auto first = [](double lo, double origin, double size, int count) {
    const double i = std::ceil((lo - origin) / size - 0.5) - 1.0;
    return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(count)));
  };
  const auto pastLast = [](double hi, double origin, double size, int count) {
    const double i = std::floor((hi - origin) / size - 0.5) + 1.0;
    return static_cast<int>(std::clamp(i, -1.0, static_cast<double>(count - 1))) + 1;
  };
  if (!usable)
    return {0, 0, f.view.width(), f.view.height()};
  return {first(box.min.x(), w.umin, f.pixelU, f.view.width()),
          first(box.min.y(), w.vmin, f.pixelV, f.view.height()),
          pastLast(box.max.x(), w.umin, f.pixelU, f.view.width()),
          pastLast(box.max.y(), w.vmin, f.pixelV, f.view.height())};
}

// The overlap holding over pixel (x, y)'s whole +-1/256 px square (the device must have seen it).
std::optional<double> robustOverlap(const ViewLineProbe& pa, const ViewLineProbe& pb,
                                    const JudgeFrame& f, int x, int y) {
  double nearestFar = std::numeric_limits<double>::infinity();
  double farthestNear = -std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 4; ++corner) {
    const double u = f.centreU(x) + ((corner & 1) ? f.edgeU : -f.edgeU);
    const double v = f.centreV(y) + ((corner & 2) ? f.edgeV : -f.edgeV);
    const std::optional<AxisRange> ra = pa.line(u, v), rb = pb.line(u, v);
    if (!ra || !rb)
      return std::nullopt;
    nearestFar = std::min({nearestFar, ra->hi, rb->hi});
    farthestNear = std::max({farthestNear, ra->lo, rb->lo});
  }
  // Over the square the near surfaces (convex functions of (u, v)) peak at a corner and the far
  // surfaces (concave) bottom out at one: this overlap holds everywhere in it.
  return nearestFar - farthestNear;
}

// What rule (a)'s search found: the largest robust overlap and how many pixels had one at all.
struct MissScan {
  double best = -std::numeric_limits<double>::infinity();
  long long robustPixels = 0;  // pixels whose whole square lies over both blocks
};

// Rule (a)'s search: the pixel with the largest robust overlap goes into j, as the one to show.
MissScan scanMiss(const raster::PixelRect& m, const JudgeFrame& f, const core::TriangleMesh& a,
                  const core::TriangleMesh& b, CgalJudgement& j) {
  MissScan scan;
  if (m.empty())
    return scan;
  const double u0 = f.centreU(m.x0) - f.edgeU, u1 = f.centreU(m.x1 - 1) + f.edgeU;
  const double v0 = f.centreV(m.y0) - f.edgeV, v1 = f.centreV(m.y1 - 1) + f.edgeV;
  const ViewLineProbe pa(a, f.view, u0, v0, u1, v1), pb(b, f.view, u0, v0, u1, v1);
  for (int y = m.y0; y < m.y1; ++y) {
    for (int x = m.x0; x < m.x1; ++x) {
      const std::optional<double> overlap = robustOverlap(pa, pb, f, x, y);
      if (!overlap)
        continue;
      ++scan.robustPixels;
      if (*overlap > scan.best) {
        scan.best = *overlap;
        j.pixelX = x;
        j.pixelY = y;
      }
    }
  }
  return scan;
}

// Rule (a): CGAL says intersect, RECODE says apart. Looks for a pixel that the device must have
// seen interfere; none means a resolution miss.
void judgeMiss(const ExactIntersection& exact, const JudgeFrame& f, const core::TriangleMesh& a,
               const core::TriangleMesh& b, CgalJudgement& j) {
  const MissScan scan = scanMiss(missSearchSpan(exact, f), f, a, b, j);
  std::ostringstream s;
  s.precision(6);
  s << "CGAL: the blocks intersect (volume " << exact.volume << ", box " << describe(exact.box.min)
    << " to " << describe(exact.box.max) << "); RECODE: apart; ";
  if (scan.robustPixels == 0) {
    j.verdict = VerdictCheck::ResolutionMiss;
    s << "resolution miss: no pixel centre of the frame lies, with its +-1/256 px square, over "
         "both blocks near the intersection";
  } else if (scan.best <= f.tolerance) {
    j.verdict = VerdictCheck::ResolutionMiss;
    s << "resolution miss: the largest overlap holding over a whole +-1/256 px pixel square is "
      << scan.best << " (" << f.inSteps(scan.best)
      << " depth steps; negative: apart there) at pixel (" << j.pixelX << ", " << j.pixelY
      << "), not above the tolerance " << f.tolerance << " (" << kDepthToleranceLsb << " steps)";
  } else {
    j.verdict = VerdictCheck::Disagree;
    s << "pixel (" << j.pixelX << ", " << j.pixelY << ") lies with its +-1/256 px square over "
      << "both blocks, which overlap there by at least " << scan.best << " ("
      << f.inSteps(scan.best) << " depth steps), beyond the tolerance " << f.tolerance << " ("
      << kDepthToleranceLsb << " steps)";
  }
  j.reason = s.str();
}

// Whether the case map covers exactly the MOR: only then can its pixels be read by position.
bool caseMapFitsMor(const core::PairResult& r) {
  return r.caseMap.rect == r.mor && r.caseMap.data.size() == static_cast<std::size_t>(r.mor.area());
}

// An interfering pixel and the blocks' depth ranges within its +-1/256 px square (nullopt: absent).
struct InterferingPixel {
  int x, y;
  double cu, cv;  // the centre on the image plane
  std::optional<AxisRange> a, b;
};

// Each interfering pixel of the MOR, row by row: rule (b) and the contact box test them alike.
template <typename Visit>
void forEachInterferingPixel(const JudgeFrame& f, const core::TriangleMesh& a,
                             const core::TriangleMesh& b, const core::PairResult& r,
                             Visit&& visit) {
  const raster::PixelRect& m = r.mor;
  const double u0 = f.centreU(m.x0) - f.edgeU, u1 = f.centreU(m.x1 - 1) + f.edgeU;
  const double v0 = f.centreV(m.y0) - f.edgeV, v1 = f.centreV(m.y1 - 1) + f.edgeV;
  const ViewLineProbe pa(a, f.view, u0, v0, u1, v1), pb(b, f.view, u0, v0, u1, v1);
  for (int y = m.y0; y < m.y1; ++y) {
    for (int x = m.x0; x < m.x1; ++x) {
      if (!core::isInterfering(r.caseMap.at(x, y)))
        continue;
      const double cu = f.centreU(x), cv = f.centreV(y);
      visit(InterferingPixel{x, y, cu, cv,
                             pa.prism(cu - f.edgeU, cv - f.edgeV, cu + f.edgeU, cv + f.edgeV),
                             pb.prism(cu - f.edgeU, cv - f.edgeV, cu + f.edgeU, cv + f.edgeV)});
    }
  }
}

// What rule (b)'s scan found: the pixel it shows goes into the judgement.
struct TouchScan {
  long long interfering = 0;
  double worstGap = -std::numeric_limits<double>::infinity();
  std::optional<std::string> missing;  // a block absent from an interfering pixel's square
};

// Rule (b)'s scan: the first pixel a block is absent from, else the widest gap, is the one shown.
TouchScan scanTouch(const JudgeFrame& f, const core::TriangleMesh& a, const core::TriangleMesh& b,
                    const core::PairResult& r, CgalJudgement& j) {
  TouchScan scan;
  forEachInterferingPixel(f, a, b, r, [&](const InterferingPixel& p) {
    ++scan.interfering;
    if (!p.a || !p.b) {
      if (!scan.missing) {
        scan.missing = std::string(!p.a ? "A" : "B");
        j.pixelX = p.x;
        j.pixelY = p.y;
      }
      return;
    }
    const double gap = std::max(p.a->lo, p.b->lo) - std::min(p.a->hi, p.b->hi);
    if (!scan.missing && gap > scan.worstGap) {
      scan.worstGap = gap;
      j.pixelX = p.x;
      j.pixelY = p.y;
    }
  });
  return scan;
}

// Rule (b): CGAL says apart, RECODE says collide. Every interfering pixel must be explained by
// rounding: both blocks within its square, their depth ranges there within the tolerance.
void judgeTouch(const JudgeFrame& f, const core::TriangleMesh& a, const core::TriangleMesh& b,
                const core::PairResult& r, CgalJudgement& j) {
  std::ostringstream s;
  s.precision(6);
  s << "CGAL: the blocks are apart; RECODE: collide; ";
  if (!caseMapFitsMor(r)) {
    j.verdict = VerdictCheck::Disagree;
    s << "the case map holds " << r.caseMap.data.size() << " pixels, the MOR "
      << static_cast<std::size_t>(r.mor.area());
    j.reason = s.str();
    return;
  }
  const TouchScan scan = scanTouch(f, a, b, r, j);
  const double worstGap = scan.worstGap;
  if (scan.interfering == 0) {
    j.verdict = VerdictCheck::Disagree;
    s << "yet its case map holds no interfering pixel";
  } else if (scan.missing) {
    j.verdict = VerdictCheck::Disagree;
    s << "block " << *scan.missing << " does not come within 1/256 px of interfering pixel ("
      << j.pixelX << ", " << j.pixelY << ")'s centre";
  } else if (worstGap > f.tolerance) {
    j.verdict = VerdictCheck::Disagree;
    s << "at interfering pixel (" << j.pixelX << ", " << j.pixelY
      << ") the blocks' depth ranges within +-1/256 px of the centre are " << worstGap << " ("
      << f.inSteps(worstGap) << " depth steps) apart, beyond the tolerance " << f.tolerance << " ("
      << kDepthToleranceLsb << " steps)";
  } else {
    j.verdict = VerdictCheck::RoundingExtra;
    s << "extra within rounding (the blocks touch within rounding): at all " << scan.interfering
      << " interfering pixels the blocks come within " << std::max(worstGap, 0.0) << " ("
      << f.inSteps(std::max(worstGap, 0.0)) << " depth steps, largest at pixel (" << j.pixelX
      << ", " << j.pixelY << ")) of each other near the centre, within the tolerance "
      << f.tolerance;
  }
  j.reason = s.str();
}

// `widened` grown by each touching pixel's square and depth range: the device's ends may lie there.
PlaneBox allowTouchingPixels(const PlaneBox& widened, const JudgeFrame& f,
                             const core::TriangleMesh& a, const core::TriangleMesh& b,
                             const core::PairResult& r, CgalJudgement& j) {
  PlaneBox allowed = widened;
  if (!caseMapFitsMor(r) || r.mor.empty())
    return allowed;
  forEachInterferingPixel(f, a, b, r, [&](const InterferingPixel& p) {
    if (!p.a || !p.b)
      return;
    const double nearEnd = std::max(p.a->lo, p.b->lo) - f.tolerance;
    const double farEnd = std::min(p.a->hi, p.b->hi) + f.tolerance;
    if (nearEnd > farEnd)
      return;  // the blocks are apart here beyond the tolerance: nothing to add
    // The square rather than the centre alone: the contact points' coordinates are computed by
    // the device's own formula and may differ from ours in the last bit.
    const Eigen::Vector3d lo(p.cu - f.edgeU, p.cv - f.edgeV, nearEnd);
    const Eigen::Vector3d hi(p.cu + f.edgeU, p.cv + f.edgeV, farEnd);
    if ((lo.array() < widened.min.array()).any() || (hi.array() > widened.max.array()).any())
      ++j.touchingPixelsOutside;
    allowed.min = allowed.min.cwiseMin(lo);
    allowed.max = allowed.max.cwiseMax(hi);
  });
  return allowed;
}

// Both collide: the contact box must lie in the exact box widened by a pixel on the image plane
// and by the depth tolerance along the axis. Where it reaches beyond, every interfering pixel
// whose blocks come within the tolerance of each other near its centre (rule (b)'s test) may
// add its +-1/256 px square and the depth range between the blocks there, widened by the
// tolerance: the device's overlap ends at such a pixel lie in that range. Faces touching within
// rounding over a wide area, whose exact intersection is a sliver, need this.
void judgeContactBox(const ExactIntersection& exact, const JudgeFrame& f,
                     const core::TriangleMesh& a, const core::TriangleMesh& b,
                     const core::PairResult& r, CgalJudgement& j) {
  std::ostringstream s;
  s.precision(6);
  s << "both intersect (exact volume " << exact.volume << ")";
  j.verdict = VerdictCheck::Agree;
  if (r.contact.box.isEmpty()) {
    s << "; no contact box measured";
    j.reason = s.str();
    return;
  }
  const PlaneBox e = toPlane(f.view, exact.box), c = toPlane(f.view, r.contact.box);
  const Eigen::Vector3d margin(f.pixelU, f.pixelV, f.tolerance);
  const PlaneBox widened{e.min - margin, e.max + margin};
  const auto beyondOf = [&](const PlaneBox& allowed) {
    return (c.max - allowed.max).cwiseMax(allowed.min - c.min).cwiseMax(0.0).eval();
  };
  const Eigen::Vector3d strictBeyond = beyondOf(widened);
  j.contactBoxInside = (strictBeyond.array() <= 0.0).all();
  j.contactBoxExplained = j.contactBoxInside;
  if (j.contactBoxInside) {
    s << "; RECODE's contact box lies within the exact box widened by one pixel and " << f.tolerance
      << " along the axis";
    j.reason = s.str();
    return;
  }
  const Eigen::Vector3d beyond = beyondOf(allowTouchingPixels(widened, f, a, b, r, j));
  j.contactBoxExplained = (beyond.array() <= 0.0).all();
  s << "; RECODE's contact box " << describe(r.contact.box.min) << " to "
    << describe(r.contact.box.max) << " reaches beyond the exact box " << describe(exact.box.min)
    << " to " << describe(exact.box.max) << " widened by one pixel (" << f.pixelU << ", "
    << f.pixelV << ") and " << f.tolerance << " along the axis, by " << strictBeyond.x() / f.pixelU
    << " px along u, " << strictBeyond.y() / f.pixelV << " px along v, "
    << f.inSteps(strictBeyond.z()) << " depth steps along the axis";
  if (j.contactBoxExplained) {
    s << "; explained: " << j.touchingPixelsOutside
      << " interfering pixels outside it are touching within rounding (the blocks come within "
      << f.tolerance << " of each other within 1/256 px of their centres)";
  } else {
    j.verdict = VerdictCheck::Disagree;
    s << "; pixels touching within rounding explain all but " << beyond.x() / f.pixelU
      << " px along u, " << beyond.y() / f.pixelV << " px along v, " << f.inSteps(beyond.z())
      << " depth steps along the axis";
  }
  j.reason = s.str();
}

void requireIndicesInRange(const core::TriangleMesh& mesh, const char* name) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const core::VertexIndex index : mesh.triangles[t])
      if (index >= mesh.vertices.size())
        throw std::invalid_argument(std::string("judgePair: ") + name + ": triangle " +
                                    std::to_string(t) + " indexes vertex " + std::to_string(index) +
                                    " of " + std::to_string(mesh.vertices.size()));
}

}  // namespace

std::string_view toString(VerdictCheck check) {
  switch (check) {
    case VerdictCheck::Agree:
      return "agree";
    case VerdictCheck::ResolutionMiss:
      return "resolution miss";
    case VerdictCheck::RoundingExtra:
      return "extra within rounding";
    case VerdictCheck::Disagree:
      return "disagree";
  }
  return "?";
}

CgalJudgement judgePair(const ExactIntersection& exact, const core::FrameSpec& frame,
                        const core::TriangleMesh& worldA, const core::TriangleMesh& worldB,
                        const core::PairResult& result) {
  requireIndicesInRange(worldA, "block A");
  requireIndicesInRange(worldB, "block B");
  const JudgeFrame f(frame, result);  // throws for an unusable frame or depth range
  CgalJudgement j;
  j.exactIntersect = exact.intersect;
  j.recodeCollide = result.collide;
  j.depthStep = f.step;
  j.depthTolerance = f.tolerance;
  if (exact.intersect && result.collide) {
    judgeContactBox(exact, f, worldA, worldB, result, j);
  } else if (exact.intersect) {
    judgeMiss(exact, f, worldA, worldB, j);
  } else if (result.collide) {
    judgeTouch(f, worldA, worldB, result, j);
  } else {
    j.verdict = VerdictCheck::Agree;
    j.reason = "both apart";
  }
  return j;
}

void CgalCounts::add(const CgalJudgement& judgement) {
  ++pairs;
  switch (judgement.verdict) {
    case VerdictCheck::Agree:
      ++agree;
      break;
    case VerdictCheck::ResolutionMiss:
      ++resolutionMisses;
      break;
    case VerdictCheck::RoundingExtra:
      ++roundingExtras;
      break;
    case VerdictCheck::Disagree:
      ++disagree;
      break;
  }
}

}  // namespace recode::verify
