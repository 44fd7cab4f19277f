#include "block_window_source.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "recode/geometry/triangle_bvh.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::core::detail {

namespace {

using raster::PixelRect;
using raster::WindowVertex;

// Whether a window range [lo, hi] (pixels, before snapping) can hold, once snapped, the centre
// i + 0.5 of a pixel with first <= i < end. Snapping moves a coordinate by at most 1/512 pixel;
// the range is widened by 1/64. The indices it can hold are [lo - 1/64 - 1/2, hi + 1/64 - 1/2]:
// when that meets [first, end - 1] and is at least 1 long, it holds an integer there (the
// common part ends at an integer bound or is the whole range), so only a range shorter than a
// pixel is rounded. Every hierarchy node and candidate triangle of a query comes here.
bool holdsCentre(double lo, double hi, int first, int end) {
  constexpr double kSnapMargin = 1.0 / 64.0;
  const double a = lo - kSnapMargin - 0.5, b = hi + kSnapMargin - 0.5;
  if (!(b >= first && a <= end - 1))
    return false;
  if (b - a >= 1.0)
    return true;
  const double i0 = std::max(std::ceil(a), static_cast<double>(first));
  const double i1 = std::min(std::floor(b), static_cast<double>(end - 1));
  return i0 <= i1;
}

// The view's mapping to window x and y, unpacked once per query so that the tests below need
// no call per box or vertex: (u - umin) / (umax - umin) * width, operation for operation as
// OrthoView::toWindow, on the coordinates toPlane picks.
struct WindowMap {
  explicit WindowMap(const OrthoView& view) {
    const int axis = view.axis() == ViewAxis::X ? 0 : view.axis() == ViewAxis::Y ? 1 : 2;
    u = (axis + 1) % 3;  // toPlane: X -> (y, z, x), Y -> (z, x, y), Z -> (x, y, z)
    v = (axis + 2) % 3;
    const ViewWindow& w = view.window();
    umin = w.umin;
    vmin = w.vmin;
    du = w.umax - w.umin;
    dv = w.vmax - w.vmin;
    width = view.width();
    height = view.height();
    sx = width / du;
    sy = height / dv;
  }
  [[nodiscard]] double x(const Eigen::Vector3d& p) const { return (p[u] - umin) / du * width; }
  [[nodiscard]] double y(const Eigen::Vector3d& p) const { return (p[v] - vmin) / dv * height; }
  // The same up to a few units in the last place (one product for a quotient and a product):
  // only for tests with holdsCentre's margin, which is far wider.
  [[nodiscard]] double nearX(double pu) const { return (pu - umin) * sx; }
  [[nodiscard]] double nearY(double pv) const { return (pv - vmin) * sy; }

  int u = 0, v = 1;
  double umin = 0.0, vmin = 0.0, du = 1.0, dv = 1.0, width = 1.0, height = 1.0, sx = 1.0, sy = 1.0;
};

// Whether a hierarchy box, moved by the pose, can hold a vertex of a triangle that covers a
// pixel centre of `rect`: the box's image-plane ranges, grown by a relative margin for the
// rounding of the world vertices (each made as linear * p + translation), mapped to the window
// by the view's own formula. That formula is monotonic, so a vertex inside the box maps inside
// the mapped range; a triangle covering a centre has that centre inside its vertices' box.
class PosedBoxTest {
 public:
  PosedBoxTest(const Eigen::Isometry3d& pose, const WindowMap& map, const PixelRect& rect)
      : identity_(pose.matrix().isIdentity(0.0)),
        linear_(pose.linear()),
        absLinear_(linear_.cwiseAbs()),
        translation_(pose.translation()),
        map_(map),
        rect_(rect) {}

  bool operator()(const Aabb& local) const {
    Eigen::Vector3d lo = local.min, hi = local.max;
    if (!identity_) {
      const Eigen::Vector3d centre = linear_ * local.center() + translation_;
      Eigen::Vector3d half = absLinear_ * (0.5 * local.extent());
      half += Eigen::Vector3d::Constant(1e-9 * (centre.cwiseAbs().maxCoeff() + half.maxCoeff()));
      lo = centre - half;
      hi = centre + half;
    }
    return holdsCentre(map_.nearX(lo[map_.u]), map_.nearX(hi[map_.u]), rect_.x0, rect_.x1) &&
           holdsCentre(map_.nearY(lo[map_.v]), map_.nearY(hi[map_.v]), rect_.y0, rect_.y1);
  }

 private:
  // Copies, made once per query: the node loop stores survivors, and through a reference the
  // compiler would have to load the pose again for every node.
  bool identity_;
  Eigen::Matrix3d linear_, absLinear_;
  Eigen::Vector3d translation_;
  WindowMap map_;
  PixelRect rect_;
};

// Whether the closed box of three window vertices, snapped as the device snaps them, holds the
// centre of a pixel of `rect`: the only triangles that can cover one (the candidates triangle
// setup makes, from the same fixed-point helpers).
bool boxHoldsPixelCentre(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                         const PixelRect& rect) {
  const auto holds = [](float p, float q, float r, int lo, int hi) {
    const std::int64_t fp = raster::snapToFixed(p), fq = raster::snapToFixed(q),
                       fr = raster::snapToFixed(r);
    const std::int64_t first =
        std::max<std::int64_t>(raster::firstPixelCentreFrom(std::min({fp, fq, fr})), lo);
    const std::int64_t last =
        std::min<std::int64_t>(raster::lastPixelCentreTo(std::max({fp, fq, fr})), hi - 1);
    return first <= last;
  };
  return holds(a.x, b.x, c.x, rect.x0, rect.x1) && holds(a.y, b.y, c.y, rect.y0, rect.y1);
}

// Whether the triangle with these snapped window x and y covers the centre of a pixel of
// `rect` under the fill rule: the device's own setup and edge functions (triangle_setup.hpp),
// evaluated at each centre of its pixel box inside `rect`. A zero-area triangle covers none.
// Past kMaxTested centres the answer is yes without looking (leaving a triangle in is always
// safe; only sub-pixel triangles come in numbers).
bool coversPixelCentre(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                       const PixelRect& rect) {
  constexpr std::int64_t kMaxTested = 16;
  const std::optional<raster::TriangleCoverage> tri =
      raster::setupCoverage(raster::snapVertex(a), raster::snapVertex(b), raster::snapVertex(c));
  if (!tri)
    return false;
  const PixelRect area = tri->bounds.intersect(rect);
  if (area.empty())
    return false;
  if (static_cast<std::int64_t>(area.width()) * area.height() > kMaxTested)
    return true;
  for (int py = area.y0; py < area.y1; ++py) {
    for (int px = area.x0; px < area.x1; ++px) {
      const std::int64_t x = raster::pixelCentreFixed(px), y = raster::pixelCentreFixed(py);
      if (tri->edges[0].at(x, y) >= 0 && tri->edges[1].at(x, y) >= 0 && tri->edges[2].at(x, y) >= 0)
        return true;
    }
  }
  return false;
}

// Whether a triangle's unsnapped image-plane box can hold a pixel centre of `rect`, with
// holdsCentre's margin for the snapping: most candidates of a hierarchy leaf end here, before
// any vertex is mapped.
bool worldBoxCanCover(const WindowMap& map, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const Eigen::Vector3d& c, const PixelRect& rect) {
  const auto [xlo, xhi] = std::minmax({a[map.u], b[map.u], c[map.u]});
  if (!holdsCentre(map.nearX(xlo), map.nearX(xhi), rect.x0, rect.x1))
    return false;
  const auto [ylo, yhi] = std::minmax({a[map.v], b[map.v], c[map.v]});
  return holdsCentre(map.nearY(ylo), map.nearY(yhi), rect.y0, rect.y1);
}

// A mesh's window vertices, each made at most once per hierarchy query: a vertex is shared by
// about six triangles, and a query meets most of them. Entries carry the number of the query
// that made them, so starting a query clears nothing and costs nothing per vertex of the
// mesh. One per thread (queries on a thread never overlap); it keeps the capacity of the
// largest mesh it has served, 16 bytes a vertex.
class WindowVertexCache {
 public:
  void startQuery(std::size_t vertexCount) {
    if (stamps_.size() < vertexCount) {
      stamps_.resize(vertexCount, 0);
      windows_.resize(vertexCount);
    }
    if (++query_ == 0) {  // the numbers wrapped: forget every entry once
      std::fill(stamps_.begin(), stamps_.end(), 0);
      query_ = 1;
    }
  }
  [[nodiscard]] const WindowVertex& get(const OrthoView& view, const TriangleMesh& mesh,
                                        VertexIndex i) {
    if (stamps_[i] != query_) {
      windows_[i] = view.toWindow(mesh.vertices[i]);
      stamps_[i] = query_;
    }
    return windows_[i];
  }

 private:
  std::uint32_t query_ = 0;
  std::vector<std::uint32_t> stamps_;
  std::vector<WindowVertex> windows_;
};

// Appends a triangle's three window vertices. Not insert with a braced list: that list is
// built on the stack in 8- and 4-byte stores and read back in 16-byte loads, which the CPU
// cannot forward (a stall that was a third of a whole-block query).
void appendTriangle(std::vector<WindowVertex>& out, const WindowVertex& a, const WindowVertex& b,
                    const WindowVertex& c) {
  out.push_back(a);
  out.push_back(b);
  out.push_back(c);
}

bool insideRange(const OrthoView& view, const Eigen::Vector3d& p, WindowVertex& out) {
  try {
    out = view.toWindow(p);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

BlockWindowSource::BlockWindowSource(const PairBlock& block, const OrthoView& view)
    : block_(block), view_(view) {
  culls_ = block.drawable() && block.hierarchy() != nullptr &&
           insideRange(view, block.box().min, corners_[0]) &&
           insideRange(view, block.box().max, corners_[1]);
  if (!culls_)
    (void)allTriangles();
}

std::optional<raster::PosedMesh> BlockWindowSource::posedMesh() const {
  if (!culls_)
    return std::nullopt;
  const std::shared_ptr<const ObjectSpaceMesh> local = block_.objectSpaceMesh();
  if (!local)
    return std::nullopt;
  const Eigen::Isometry3d& pose = block_.localToWorld();
  return raster::PosedMesh{local->xyz,
                           local->indices,
                           {rasterPose(pose.linear(), pose.translation()), view_.windowMapping()},
                           local->key,
                           local};
}

std::span<const WindowVertex> BlockWindowSource::extremes() const {
  if (culls_)
    return corners_;
  return all_;
}

raster::TriangleDraw BlockWindowSource::allTriangles() const {
  if (!allMade_) {
    all_ = view_.toWindow(block_.mesh());
    allIndices_ = triangleIndices(block_.mesh());
    allMade_ = true;
  }
  return {all_, allIndices_};
}

std::optional<raster::TriangleDraw> BlockWindowSource::trianglesMeeting(
    const PixelRect& rect) const {
  if (!culls_)
    return std::nullopt;
  if (!nearRect_ || !(*nearRect_ == rect)) {
    if (baseRect_ && !rect.empty() && baseRect_->intersect(rect) == rect) {
      narrow(rect);
    } else {
      gather(rect);
      near_ = base_;
    }
    nearRect_ = rect;
  }
  if (sequence_.size() < near_.size()) {
    const auto from = static_cast<std::uint32_t>(sequence_.size());
    sequence_.resize(near_.size());
    for (auto i = from; i < sequence_.size(); ++i)
      sequence_[i] = i;
  }
  return raster::TriangleDraw{near_, std::span(sequence_).first(near_.size())};
}

void BlockWindowSource::gather(const PixelRect& rect) const {
  baseRect_ = rect;
  base_.clear();
  if (rect.empty())
    return;
  const WindowMap map(view_);
  const PosedBoxTest boxCanCover(block_.localToWorld(), map, rect);
  const TriangleMesh& mesh = block_.mesh();
  thread_local WindowVertexCache threadWindows;
  thread_local std::vector<std::uint32_t> threadSurvivors;
  thread_local std::vector<std::uint64_t> threadBits;
  // Plain references: a lambda naming a thread_local itself would look it up at every use.
  WindowVertexCache& windows = threadWindows;
  std::vector<std::uint32_t>& survivors = threadSurvivors;
  windows.startQuery(mesh.vertices.size());
  survivors.clear();
  // When the rectangle holds most of the block, nearly every node and triangle passes the box
  // tests, so they cost more than they leave out, and so does the coverage test, which sets up
  // most triangles the device then sets up again: every triangle whose snapped box holds a
  // pixel centre of the rectangle is kept, in the block's order. A kept triangle that covers no
  // centre writes nothing, so the bits are those of the other path.
  if (mostlyInside(rect)) {
    for (const Triangle& tri : mesh.triangles) {
      const WindowVertex& a = windows.get(view_, mesh, tri[0]);
      const WindowVertex& b = windows.get(view_, mesh, tri[1]);
      const WindowVertex& c = windows.get(view_, mesh, tri[2]);
      if (boxHoldsPixelCentre(a, b, c, rect))
        appendTriangle(base_, a, b, c);
    }
    return;
  }
  // Only x and y decide; the survivors are listed in the block's order afterwards.
  block_.hierarchy()->visit(boxCanCover, [&](std::uint32_t t) {
    const Triangle& tri = mesh.triangles[t];
    if (!worldBoxCanCover(map, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]],
                          rect))
      return;
    const WindowVertex& a = windows.get(view_, mesh, tri[0]);
    const WindowVertex& b = windows.get(view_, mesh, tri[1]);
    const WindowVertex& c = windows.get(view_, mesh, tri[2]);
    if (boxHoldsPixelCentre(a, b, c, rect) && coversPixelCentre(a, b, c, rect))
      survivors.push_back(t);
  });
  sortDistinctIds(survivors, mesh.triangles.size(), threadBits);
  base_.reserve(3 * survivors.size());
  for (const std::uint32_t t : survivors)
    for (const VertexIndex i : mesh.triangles[t])
      base_.push_back(windows.get(view_, mesh, i));
}

bool BlockWindowSource::mostlyInside(const PixelRect& rect) const {
  const double x0 = corners_[0].x, y0 = corners_[0].y, x1 = corners_[1].x, y1 = corners_[1].y;
  const double ix = std::min<double>(x1, rect.x1) - std::max<double>(x0, rect.x0);
  const double iy = std::min<double>(y1, rect.y1) - std::max<double>(y0, rect.y0);
  if (ix <= 0.0 || iy <= 0.0)
    return false;
  return ix * iy >= 0.5 * (x1 - x0) * (y1 - y0);
}

void BlockWindowSource::narrow(const PixelRect& rect) const {
  narrowed_.clear();
  for (std::size_t k = 0; k + 2 < base_.size(); k += 3)
    if (boxHoldsPixelCentre(base_[k], base_[k + 1], base_[k + 2], rect) &&
        coversPixelCentre(base_[k], base_[k + 1], base_[k + 2], rect))
      appendTriangle(narrowed_, base_[k], base_[k + 1], base_[k + 2]);
  near_ = narrowed_;
}

}  // namespace recode::core::detail
