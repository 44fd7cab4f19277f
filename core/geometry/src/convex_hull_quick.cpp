// The incremental step of the convex hull, in the manner of Quickhull: every point not yet
// inside the hull waits in the outside set of one face it lies strictly in front of; a face's
// farthest waiting point is added by removing the faces it sees (found by a walk over
// neighbours from that face: the faces a point outside a convex polytope sees form one
// connected region) and joining it to the region's boundary. Whether a point sees a face is
// decided by the exact orient3d, so the result is the exact hull; a point on a face's plane
// does not see it, which keeps every triangle non-degenerate but can leave non-corner points
// on planar faces (removed by the facet step).

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "convex_hull_detail.hpp"
#include "recode/geometry/exact_predicates.hpp"

namespace recode::core::detail {
namespace {

constexpr std::size_t kNoFace = std::numeric_limits<std::size_t>::max();

struct Face {
  Triangle v;
  // The face across edge v[i] -> v[i + 1], in the same direction reversed.
  std::array<std::size_t, 3> neighbour{kNoFace, kNoFace, kNoFace};
  bool alive = true;
  std::vector<VertexIndex> outside;  // points strictly in front of this face
  // The last eye that looked at this face (addFarthestPoint's walk) and what it saw.
  std::size_t visitedBy = kNoFace;
  bool visible = false;
};

Face faceOf(const Triangle& t) {
  Face f;
  f.v = t;
  return f;
}

class QuickHull {
 public:
  explicit QuickHull(std::span<const Eigen::Vector3d> points) : points_(points) {}

  std::vector<Triangle> run() {
    newFaceFrom_.assign(points_.size(), kNoFace);
    start();
    while (!pending_.empty()) {
      const std::size_t f = pending_.back();
      pending_.pop_back();
      if (faces_[f].alive && !faces_[f].outside.empty())
        addFarthestPoint(f);
    }
    std::vector<Triangle> result;
    for (const Face& face : faces_) {
      if (face.alive)
        result.push_back(face.v);
    }
    return result;
  }

 private:
  [[nodiscard]] const Eigen::Vector3d& p(VertexIndex i) const { return points_[i]; }

  // True when point q lies strictly in front of face f (on its outer side).
  [[nodiscard]] bool sees(VertexIndex q, std::size_t f) const {
    const Triangle& t = faces_[f].v;
    return orient3d(p(t[0]), p(t[1]), p(t[2]), p(q)) < 0;
  }

  // An approximate distance in front of the face's plane, scaled by its area: only to choose
  // which point to add first (any point that sees the face would do).
  [[nodiscard]] double height(VertexIndex q, const Triangle& t) const {
    const Eigen::Vector3d n = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
    return n.dot(p(q) - p(t[0]));
  }

  // A tetrahedron of four points spanning a volume, then every other point into an outside set.
  void start() {
    const std::array<VertexIndex, 4> s = simplex();
    for (int skip = 0; skip < 4; ++skip) {
      Triangle t{};
      int k = 0;
      for (int i = 0; i < 4; ++i) {
        if (i != skip)
          t[static_cast<std::size_t>(k++)] = s[static_cast<std::size_t>(i)];
      }
      // Outward: the fourth point lies behind (below) the face.
      if (orient3d(p(t[0]), p(t[1]), p(t[2]), p(s[static_cast<std::size_t>(skip)])) < 0)
        std::swap(t[1], t[2]);
      faces_.push_back(faceOf(t));
    }
    // Each edge of the tetrahedron is shared by the two faces that hold its ends.
    for (std::size_t f = 0; f < 4; ++f)
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t g = 0; g < 4; ++g)
          if (g != f) {
            const std::size_t j = edgeIndex(faces_[g].v, faces_[f].v[(i + 1) % 3], faces_[f].v[i]);
            if (j < 3)
              faces_[f].neighbour[i] = g;
          }
    std::vector<VertexIndex> rest;
    for (VertexIndex i = 0; i < points_.size(); ++i) {
      if (std::find(s.begin(), s.end(), i) == s.end())
        rest.push_back(i);
    }
    assign(rest, 0);
  }

  // Four points spanning a volume: the lowest point, the one farthest from it, the one farthest
  // from their line, the one farthest from their plane (farthest in double arithmetic, checked
  // exactly; the caller has made sure such points exist).
  [[nodiscard]] std::array<VertexIndex, 4> simplex() const {
    const std::size_t n = points_.size();
    const auto lexLess = [&](VertexIndex a, VertexIndex b) {
      return std::lexicographical_compare(p(a).data(), p(a).data() + 3, p(b).data(),
                                          p(b).data() + 3);
    };
    std::vector<VertexIndex> all(n);
    std::iota(all.begin(), all.end(), VertexIndex{0});
    const VertexIndex a = *std::min_element(all.begin(), all.end(), lexLess);
    // The highest-scoring point the exact test accepts, ties to the lower index: a heap, so
    // that the usual case (the first candidate passes) costs one pass, not a sort.
    const auto firstExact = [&](auto score, auto accept) {
      std::vector<std::pair<double, VertexIndex>> ranked;
      ranked.reserve(n);
      for (VertexIndex i = 0; i < n; ++i)
        ranked.emplace_back(-score(i), i);
      const auto after = std::greater<std::pair<double, VertexIndex>>();
      std::make_heap(ranked.begin(), ranked.end(), after);
      while (!ranked.empty()) {
        std::pop_heap(ranked.begin(), ranked.end(), after);
        const VertexIndex i = ranked.back().second;
        ranked.pop_back();
        if (accept(i))
          return i;
      }
      return std::numeric_limits<VertexIndex>::max();
    };
    const VertexIndex b = firstExact([&](VertexIndex i) { return (p(i) - p(a)).squaredNorm(); },
                                     [&](VertexIndex i) { return p(i) != p(a); });
    const VertexIndex c =
        firstExact([&](VertexIndex i) { return (p(b) - p(a)).cross(p(i) - p(a)).squaredNorm(); },
                   [&](VertexIndex i) { return !collinear(p(a), p(b), p(i)); });
    const VertexIndex d = firstExact(
        [&](VertexIndex i) { return std::abs((p(b) - p(a)).cross(p(c) - p(a)).dot(p(i) - p(a))); },
        [&](VertexIndex i) { return orient3d(p(a), p(b), p(c), p(i)) != 0; });
    return {a, b, c, d};
  }

  // The index i of the directed edge from -> to in t (t[i] == from, t[i + 1] == to), or 3.
  static std::size_t edgeIndex(const Triangle& t, VertexIndex from, VertexIndex to) {
    for (std::size_t i = 0; i < 3; ++i)
      if (t[i] == from && t[(i + 1) % 3] == to)
        return i;
    return 3;
  }

  // Puts each point into the outside set of the first face from `firstFace` on that it sees;
  // a point that sees none is inside (or on) the hull and is dropped.
  void assign(const std::vector<VertexIndex>& candidates, std::size_t firstFace) {
    for (const VertexIndex q : candidates) {
      for (std::size_t f = firstFace; f < faces_.size(); ++f) {
        if (faces_[f].alive && sees(q, f)) {
          faces_[f].outside.push_back(q);
          break;
        }
      }
    }
    for (std::size_t f = firstFace; f < faces_.size(); ++f) {
      if (faces_[f].alive && !faces_[f].outside.empty())
        pending_.push_back(f);
    }
  }

  void addFarthestPoint(std::size_t start) {
    const Triangle startFace = faces_[start].v;
    const std::vector<VertexIndex>& waiting = faces_[start].outside;
    const VertexIndex eye = *std::max_element(
        waiting.begin(), waiting.end(),
        [&](VertexIndex x, VertexIndex y) { return height(x, startFace) < height(y, startFace); });

    // The faces the eye sees, by a walk over neighbours; the boundary edges on the way, each
    // with the face beyond it that stays.
    struct HorizonEdge {
      VertexIndex u, v;
      std::size_t beyond;
    };
    std::vector<std::size_t> visible{start};
    faces_[start].visitedBy = eye;
    faces_[start].visible = true;
    std::vector<HorizonEdge> horizon;
    for (std::size_t k = 0; k < visible.size(); ++k) {
      const Face& face = faces_[visible[k]];
      for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t g = face.neighbour[i];
        Face& other = faces_[g];
        if (other.visitedBy != eye) {
          other.visitedBy = eye;
          other.visible = sees(eye, g);
          if (other.visible)
            visible.push_back(g);
        }
        if (!other.visible)
          horizon.push_back({face.v[i], face.v[(i + 1) % 3], g});
      }
    }

    std::vector<VertexIndex> orphans;
    for (const std::size_t f : visible) {
      Face& face = faces_[f];
      face.alive = false;
      for (const VertexIndex q : face.outside) {
        if (q != eye)
          orphans.push_back(q);
      }
      face.outside.clear();
      face.outside.shrink_to_fit();
    }
    // A new face (u, v, eye) per horizon edge: across u -> v the face that stays; across
    // v -> eye the new face of the horizon edge that starts at v, across eye -> u the one that
    // ends at u (the horizon is one cycle).
    const std::size_t firstNew = faces_.size();
    for (const HorizonEdge& e : horizon) {
      const std::size_t f = faces_.size();
      faces_.push_back(faceOf({e.u, e.v, eye}));
      faces_[f].neighbour[0] = e.beyond;
      Face& beyond = faces_[e.beyond];
      beyond.neighbour[edgeIndex(beyond.v, e.v, e.u)] = f;
      newFaceFrom_[e.u] = f;
    }
    for (std::size_t f = firstNew; f < faces_.size(); ++f) {
      Face& face = faces_[f];
      face.neighbour[1] = newFaceFrom_[face.v[1]];
      faces_[face.neighbour[1]].neighbour[2] = f;
    }
    assign(orphans, firstNew);
  }

  std::span<const Eigen::Vector3d> points_;
  std::vector<Face> faces_;
  std::vector<std::size_t> pending_;      // faces that may have outside points
  std::vector<std::size_t> newFaceFrom_;  // per horizon vertex u, the new face (u, v, eye)
};

}  // namespace

std::vector<Triangle> quickHullTriangles(std::span<const Eigen::Vector3d> points) {
  return QuickHull(points).run();
}

}  // namespace recode::core::detail
