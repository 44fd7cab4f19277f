#pragma once
// A mesh as CGAL's exact kernel holds it, shared by the CGAL oracles (cgal_oracle.cpp,
// cgal_layer_oracle.cpp): private, since it names CGAL types.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"

namespace recode::verify::cgal {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<Kernel::Point_3>;

// An exact copy: the double coordinates are exact rationals. The callers' validation has
// already checked that the mesh is closed and consistently oriented; the checks here guard
// CGAL's own preconditions all the same (core::MeshError naming `name`).
inline ExactMesh toExactMesh(const core::TriangleMesh& mesh, const std::string& name) {
  ExactMesh out;
  std::vector<ExactMesh::Vertex_index> ids;
  ids.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p : mesh.vertices)
    ids.push_back(out.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const core::Triangle& tri = mesh.triangles[t];
    if (out.add_face(ids[tri[0]], ids[tri[1]], ids[tri[2]]) == ExactMesh::null_face())
      throw core::MeshError(name + ": triangle " + std::to_string(t) +
                            " does not fit its neighbours as a manifold surface");
  }
  if (!CGAL::is_closed(out))
    throw core::MeshError(name + ": the surface is not closed");
  return out;
}

}  // namespace recode::verify::cgal
