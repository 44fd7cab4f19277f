// Stage 6 of checkClosedMesh: the orientation of each shell (connected piece of the surface)
// agrees with where it lies. Once no two triangles meet (stage 5), the shells are disjoint
// closed surfaces; each bounds a region, and the winding number of the whole surface at a point
// is the sum over the shells that enclose it of +1 (shell facing outward, positive volume) or -1
// (facing inward). The surface bounds a solid when that sum is 0 or 1 everywhere off it. Just
// outside shell S the sum is W, the winding number of the other shells at S (constant over S,
// which meets none of them); just inside it is W + sign(S). Every region borders some shell, so
// it suffices that for each shell: W = 0 and S faces outward (S bounds the solid from outside),
// or W = 1 and S faces inward (S bounds a cavity in the solid).
//
// W is counted exactly along a ray from one vertex of S in the +x direction: each crossing of
// another shell's triangle adds the sign of that triangle's normal's x component. The ray is
// perturbed symbolically (its start moved by (0, e, e^2) for an infinitesimal e), so it never
// passes through an edge or a vertex and the count needs no tie-breaking tolerance.

#include <cstdint>
#include <string>
#include <vector>

#include "format.hpp"
#include "recode/geometry/exact_predicates.hpp"
#include "recode/geometry/triangle_bvh.hpp"
#include "validate_stages.hpp"

namespace recode::core::detail {
namespace {

// The shells: each triangle's shell, numbered in the order of their first triangles.
struct Shells {
  std::vector<std::uint32_t> ofTriangle;
  std::vector<std::uint32_t> firstTriangle;  // per shell
  std::vector<std::uint32_t> triangleCount;  // per shell
};

Shells findShells(const TriangleMesh& mesh) {
  DisjointSets sets(mesh.vertices.size());
  for (const Triangle& tri : mesh.triangles) {
    sets.unite(tri[0], tri[1]);
    sets.unite(tri[0], tri[2]);
  }
  constexpr std::uint32_t kNone = UINT32_MAX;
  std::vector<std::uint32_t> shellOfRoot(mesh.vertices.size(), kNone);
  Shells shells;
  shells.ofTriangle.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::uint32_t& shell = shellOfRoot[sets.find(mesh.triangles[t][0])];
    if (shell == kNone) {
      shell = static_cast<std::uint32_t>(shells.firstTriangle.size());
      shells.firstTriangle.push_back(static_cast<std::uint32_t>(t));
      shells.triangleCount.push_back(0);
    }
    shells.ofTriangle[t] = shell;
    ++shells.triangleCount[shell];
  }
  return shells;
}

// Each shell's signed volume (mesh.hpp's signedVolume, shell by shell, about the centre of the
// shell's own box).
std::vector<double> shellVolumes(const TriangleMesh& mesh, const Shells& shells) {
  std::vector<Aabb> boxes(shells.firstTriangle.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const VertexIndex v : mesh.triangles[t]) {
      boxes[shells.ofTriangle[t]].extend(mesh.vertices[v]);
    }
  }
  std::vector<double> volumes(boxes.size(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t s = shells.ofTriangle[t];
    const Eigen::Vector3d o = boxes[s].center();
    const Triangle& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.vertices[tri[0]] - o;
    const Eigen::Vector3d b = mesh.vertices[tri[1]] - o;
    const Eigen::Vector3d c = mesh.vertices[tri[2]] - o;
    volumes[s] += a.dot(b.cross(c)) / 6.0;
  }
  return volumes;
}

// The sign of orient2d(a, b, p) on the (y, z) plane with p moved by (e, e^2): the exact sign
// when it is not 0, else the sign of the first non-zero term of its expansion in e,
// (a.z - b.z) e + (b.y - a.y) e^2.
int perturbedSide(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& p) {
  const int side = orient2d(a, b, p, 1, 2);
  if (side != 0) {
    return side;
  }
  if (a.z() != b.z()) {
    return a.z() > b.z() ? 1 : -1;
  }
  return b.y() > a.y() ? 1 : (b.y() < a.y() ? -1 : 0);
}

// The winding number about p of the triangles of every shell but `own`: the signed count of
// their crossings by the perturbed ray from p towards +x.
int windingAround(const TriangleMesh& mesh, const TriangleBvh& bvh, const Shells& shells,
                  std::uint32_t own, const Eigen::Vector3d& p) {
  int winding = 0;
  const auto reaches = [&p](const Aabb& box) {
    return box.max.x() >= p.x() && box.min.y() <= p.y() && p.y() <= box.max.y() &&
           box.min.z() <= p.z() && p.z() <= box.max.z();
  };
  bvh.visit(reaches, [&](std::uint32_t t) {
    if (shells.ofTriangle[t] == own) {
      return;
    }
    const Triangle& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    // Inside the triangle's (y, z) shadow when all three edges see p on the same side; that
    // side is the sign of the normal's x component.
    const int side = perturbedSide(a, b, p);
    if (side == 0 || perturbedSide(b, c, p) != side || perturbedSide(c, a, p) != side) {
      return;
    }
    // The crossing lies ahead of p when p is behind the plane as seen along the ray.
    if (orient3d(a, b, c, p) == side) {
      winding += side;
    }
  });
  return winding;
}

std::string shellName(const Shells& shells, std::uint32_t s) {
  return "the shell of triangle " + std::to_string(shells.firstTriangle[s]) + " (" +
         std::to_string(shells.triangleCount[s]) + " triangles; the mesh has " +
         std::to_string(shells.firstTriangle.size()) + " shells)";
}

constexpr const char* kReverse = "reverse the winding of its triangles (swap two indices of each)";

// Records the problem, if any, of shell s with signed volume `volume` and winding number
// `winding` of the other shells at its vertex v. Returns true if the limit is reached.
bool recordShell(const Shells& shells, std::uint32_t s, double volume, int winding, VertexIndex v,
                 Recorder& recorder) {
  const bool single = shells.firstTriangle.size() == 1;
  if (winding == 0 && !(volume > 0.0)) {
    if (single) {
      return recorder.add(MeshProblemKind::InwardOrientation,
                          "signed volume is " + formatDouble(volume) +
                              " (must be > 0): the faces point inward; reverse the winding of "
                              "every triangle (swap two indices of each)");
    }
    return recorder.add(MeshProblemKind::InwardOrientation,
                        shellName(shells, s) + " has signed volume " + formatDouble(volume) +
                            " and lies inside no other shell: its faces point inward; " + kReverse);
  }
  if (winding == 1 && volume > 0.0) {
    return recorder.add(MeshProblemKind::NestedShell,
                        shellName(shells, s) + " faces outward (signed volume " +
                            formatDouble(volume) + ") but lies inside the solid of the others " +
                            "(its vertex " + std::to_string(v) +
                            " has winding number 1): that space would be solid twice; if it "
                            "bounds a cavity, " +
                            kReverse + ", else remove it or move it out");
  }
  if (winding != 0 && winding != 1) {
    return recorder.add(MeshProblemKind::NestedShell,
                        "the other shells wind " + std::to_string(winding) + " times around " +
                            shellName(shells, s) + " (at its vertex " + std::to_string(v) +
                            "): shells may nest only as solid, cavity, solid, ..., each facing "
                            "away from the solid it bounds; reverse or remove the shells "
                            "around it");
  }
  return false;
}

}  // namespace

void checkShellNesting(const TriangleMesh& mesh, Recorder& recorder) {
  const Shells shells = findShells(mesh);
  const std::vector<double> volumes = shellVolumes(mesh, shells);
  const std::size_t count = shells.firstTriangle.size();
  if (count == 1) {
    recordShell(shells, 0, volumes[0], 0, mesh.triangles[0][0], recorder);
    return;
  }
  const TriangleBvh bvh(mesh);
  for (std::uint32_t s = 0; s < count; ++s) {
    const VertexIndex v = mesh.triangles[shells.firstTriangle[s]][0];
    const int winding = windingAround(mesh, bvh, shells, s, mesh.vertices[v]);
    if (recordShell(shells, s, volumes[s], winding, v, recorder)) {
      return;
    }
  }
}

}  // namespace recode::core::detail
