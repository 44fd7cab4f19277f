#pragma once
// Reading triangle meshes from Wavefront OBJ, OFF, STL and PLY files.
//
// The OBJ and OFF readers keep every vertex of the file in file order (vertex k of the file is
// mesh.vertices[k]) and fan-triangulate each polygon v0 v1 ... v(n-1) into
// (v0, v1, v2), (v0, v2, v3), ..., (v0, v(n-2), v(n-1)), keeping its winding. They check
// the file's syntax, that coordinates are finite and that face indices are in range; they
// do not check that the result is a valid convex block (see validate.hpp).
//
// Errors throw MeshError with a message "<path>:<line>: <problem>" when the problem belongs
// to a line, else "<path>: <problem>". docs/geometry.md lists the messages.

#include <filesystem>
#include <string>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"

namespace recode::core {

// Wavefront OBJ, parsed by tinyobjloader (double precision). Only `v` positions and `f`
// faces are used; normals, texture coordinates, groups, materials, lines and points are
// ignored (material libraries are not opened). Because tinyobjloader silently replaces
// malformed numbers by defaults, the reader first checks every `v` and `f` line itself:
// a `v` line needs at least three finite numbers (more are allowed: w or a colour); an
// `f` line needs at least three vertex references whose vertex index is a non-zero integer
// in range (negative indices count back from the last vertex defined so far).
[[nodiscard]] TriangleMesh readObj(const std::filesystem::path& path);

// One object or group of an OBJ file: its name and the faces under it.
struct MeshGroup {
  std::string name;   // the `o` or `g` record's name, "(unnamed)" for faces before any
  TriangleMesh mesh;  // the file's vertices its faces use (in file order), renumbered
};

// An OBJ file read as readObj does, split at its `o` and `g` records (convex decompositions
// such as V-HACD and CoACD write each piece as `o convex_0`, `o convex_1`, ...): one group per
// distinct name that has faces, in the order the names first appear; faces under a name used
// twice join its group. A group is not validated. Errors as readObj's, and
// "<path>: only an OBJ file has groups ..." for another extension.
[[nodiscard]] std::vector<MeshGroup> readObjGroups(const std::filesystem::path& path);

// OFF: the keyword "OFF" on the first non-blank line (optionally followed by the counts on
// the same line), then "numVertices numFaces [numEdges]", then one vertex per line (exactly
// three finite numbers), then one face per line ("n i0 i1 ... i(n-1)", n >= 3, indices
// 0-based; anything after the n indices, such as a colour, is ignored). '#' starts a comment
// that runs to the end of the line; blank lines are skipped. Nothing but comments and blank
// lines may follow the last face.
[[nodiscard]] TriangleMesh readOff(const std::filesystem::path& path);

// STL, binary or ASCII. A file whose size is exactly 84 + 50 n bytes, n the triangle count in
// bytes 80-83 (little endian), is binary (even if its header starts with "solid"); otherwise it
// must be ASCII, one statement a line: "solid [name]", then per triangle "facet normal nx ny nz",
// "outer loop", exactly three "vertex x y z" lines (finite numbers), "endloop", "endfacet", and
// "endsolid [name]"; several solids may follow one another. Normals and attribute bytes are
// ignored. STL stores corners by value: corners with exactly equal coordinates become one
// vertex (no tolerance), numbered in order of first appearance; the triangles keep the file's
// order and corner order. Binary coordinates are floats, read exactly; ASCII ones are read as
// doubles, correctly rounded, as OBJ and OFF are.
[[nodiscard]] TriangleMesh readStl(const std::filesystem::path& path);

// PLY, ASCII or binary (either byte order): the `vertex` element's x, y, z and the `face`
// element's `vertex_indices` (or `vertex_index`) lists; other elements and properties are
// ignored. The header is checked here (grammar, and that every declared element fits in the
// bytes after it, so no count can make the reader allocate beyond the file's size); the body is
// parsed by assimp, with no post-processing, in single precision (coordinates are rounded to
// float). Vertices keep file order; faces are fan-triangulated in file order as OFF faces are.
// A build without assimp (docs/geometry.md) throws "<path>: this build of RECODE has no PLY
// reader ..." for every PLY file whose header is valid.
[[nodiscard]] TriangleMesh readPly(const std::filesystem::path& path);

// Chooses the reader by the file extension, ignoring case: ".obj", ".off", ".stl" or ".ply".
[[nodiscard]] TriangleMesh readMesh(const std::filesystem::path& path);

}  // namespace recode::core
