// ConvexBlock, ClosedMesh and CollisionGeometry (recode/api/geometry.hpp), and the primitive
// solids of recode/geometry/generators.hpp as ready-made blocks (a torus as a closed mesh). The API
// shares its shapes as std::shared_ptr<const T>; Python holds the same objects (shapes are
// immutable: the module exposes no way to change one).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "pickle_state.hpp"
#include "recode/api/geometry.hpp"
#include "recode/geometry/generators.hpp"

namespace recode::python {

namespace {

using BlockHolder = std::shared_ptr<ConvexBlock>;
using ClosedHolder = std::shared_ptr<ClosedMesh>;
using GeometryHolder = std::shared_ptr<CollisionGeometry>;

BlockHolder held(ConvexBlockPtr block) {
  return std::const_pointer_cast<ConvexBlock>(block);
}
ClosedHolder held(ClosedMeshPtr mesh) {
  return std::const_pointer_cast<ClosedMesh>(mesh);
}
GeometryHolder held(CollisionGeometryPtr g) {
  return std::const_pointer_cast<CollisionGeometry>(g);
}
BlockHolder heldBlock(const py::handle& block) {
  return block.cast<BlockHolder>();
}

// A missing mesh file is FileNotFoundError, as open() raises it; anything wrong inside a file
// is the reader's MeshError.
void requireFile(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path))
    fileNotFound("no such mesh file", path.string());
}

BlockHolder blockFromFile(const std::filesystem::path& path) {
  requireFile(path);
  return held(ConvexBlock::fromFile(path));
}

BlockHolder blockFromHull(const py::handle& points, std::string name) {
  const std::vector<Eigen::Vector3d> p = verticesFrom(points, "points");
  return held(ConvexBlock::fromHull(p, std::move(name)));
}

BlockHolder blockFromArrays(const py::handle& vertices, const py::handle& faces, std::string name) {
  const std::vector<Eigen::Vector3d> v = verticesFrom(vertices, "vertices");
  const std::vector<core::Triangle> f = facesFrom(faces, v.size(), "faces");
  return held(ConvexBlock::fromArrays(v, f, std::move(name)));
}

ClosedHolder closedFromFile(const std::filesystem::path& path) {
  requireFile(path);
  return held(ClosedMesh::fromFile(path));
}

ClosedHolder closedFromArrays(const py::handle& vertices, const py::handle& faces,
                              std::string name) {
  const std::vector<Eigen::Vector3d> v = verticesFrom(vertices, "vertices");
  const std::vector<core::Triangle> f = facesFrom(faces, v.size(), "faces");
  return held(ClosedMesh::fromArrays(v, f, std::move(name)));
}

// One part of a compound: a block (at the identity) or a (block, pose) pair.
BlockPart partFrom(const py::handle& item, std::size_t index) {
  const std::string what = "parts[" + std::to_string(index) + "]";
  if (py::isinstance<ConvexBlock>(item))
    return {heldBlock(item), Eigen::Isometry3d::Identity()};
  if (py::isinstance<py::tuple>(item) && py::len(item) == 2 &&
      py::isinstance<ConvexBlock>(item[py::int_(0)])) {
    BlockPart part{heldBlock(item[py::int_(0)]), Eigen::Isometry3d::Identity()};
    try {
      part.pose = poseFrom(item[py::int_(1)]);
    } catch (const py::value_error& e) {
      throw py::value_error(what + ": " + e.what());
    }
    return part;
  }
  if (py::isinstance<ClosedMesh>(item))
    throw py::type_error(what +
                         ": a ClosedMesh cannot be part of a compound (the layered pair takes one "
                         "solid on each side): use CollisionGeometry.closed(mesh) alone");
  throw py::type_error(what + ": expected a ConvexBlock or a (ConvexBlock, 4 x 4 pose) tuple");
}

// Block i of g; an IndexError naming the block count for an index past it (the C++ API's
// std::out_of_range would carry the standard library's wording).
const BlockPart& partAt(const CollisionGeometry& g, std::size_t i) {
  if (g.isClosed())
    throw py::value_error("the geometry '" + g.name() +
                          "' is a closed mesh, not convex blocks: read its closed_mesh");
  if (i >= g.blockCount())
    throw py::index_error("index " + std::to_string(i) + " is out of range: the geometry has " +
                          std::to_string(g.blockCount()) +
                          (g.blockCount() == 1 ? " block" : " blocks"));
  return g.part(i);
}

BlockHolder blockFromFileHull(const std::filesystem::path& path) {
  requireFile(path);
  return held(ConvexBlock::fromFileHull(path));
}

// The mesh's triangles as an (m, 3) uint32 array (a copy: Triangle is std::array).
template <class Shape>
py::array_t<core::VertexIndex> facesOf(const Shape& shape) {
  const auto& triangles = shape.mesh().triangles;
  py::array_t<core::VertexIndex> out({static_cast<long>(triangles.size()), 3L});
  core::VertexIndex* flat = out.mutable_data();
  for (const core::Triangle& t : triangles)
    flat = std::copy(t.begin(), t.end(), flat);
  return out;
}

GeometryHolder compoundFrom(const py::sequence& parts, std::string name) {
  std::vector<BlockPart> list;
  for (std::size_t i = 0; i < py::len(parts); ++i)
    list.push_back(partFrom(parts[i], i));
  return held(CollisionGeometry::compound(std::move(list), std::move(name)));
}

GeometryHolder geometryFromObjGroups(const std::filesystem::path& path, bool hull) {
  requireFile(path);
  return held(CollisionGeometry::fromObjGroups(path, hull));
}

constexpr const char* kBlockType = "recode.ConvexBlock";
constexpr const char* kClosedType = "recode.ClosedMesh";
constexpr const char* kGeometryType = "recode.CollisionGeometry";

// A block's or closed mesh's state: (format, name, vertices (n, 3), faces (m, 3)); made again
// through fromArrays, so validated again.
template <class Shape>
py::tuple shapeState(const Shape& shape) {
  return makeState(shape.name(), pointsState(shape.mesh().vertices), facesOf(shape));
}
template <class Shape>
std::shared_ptr<Shape> shapeFromState(const py::tuple& state, const char* type) {
  checkState(state, type, 3);
  const std::vector<Eigen::Vector3d> v = pointsFromState(state[2], type, "vertices");
  const std::vector<core::Triangle> f = facesFrom(state[3], v.size(), "faces");
  return held(Shape::fromArrays(v, f, stateItem<std::string>(state[1], type, "name")));
}
BlockHolder blockFromState(const py::tuple& state) {
  return shapeFromState<ConvexBlock>(state, kBlockType);
}
ClosedHolder closedFromState(const py::tuple& state) {
  return shapeFromState<ClosedMesh>(state, kClosedType);
}

// (format, name, single, [blocks], poses (n, 4, 4)): single() and compound() build different
// trees (a leaf alone, or a root over the leaves), so which one made it is kept. A closed mesh's
// geometry is single, its one "block" the ClosedMesh, at the identity.
py::tuple geometryState(const CollisionGeometry& g) {
  if (g.isClosed()) {
    py::array_t<double> identity({py::ssize_t{1}, py::ssize_t{4}, py::ssize_t{4}});
    double* p = identity.mutable_data();
    for (int k = 0; k < 16; ++k)
      p[k] = k % 5 == 0 ? 1.0 : 0.0;  // the diagonal of a row-major 4 x 4
    py::list blocks;
    blocks.append(held(g.closedMesh()));
    return makeState(g.name(), true, blocks, identity);
  }
  py::list blocks;
  py::array_t<double> poses(
      {static_cast<py::ssize_t>(g.blockCount()), py::ssize_t{4}, py::ssize_t{4}});
  double* p = poses.mutable_data();
  for (std::size_t i = 0; i < g.blockCount(); ++i) {
    blocks.append(held(g.part(i).block));
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        *p++ = g.part(i).pose.matrix()(r, c);
  }
  const bool single = g.tree().nodes().size() == 1;
  return makeState(g.tree().name(), single, blocks, poses);
}
GeometryHolder geometryFromState(const py::tuple& state) {
  checkState(state, kGeometryType, 4);
  auto name = stateItem<std::string>(state[1], kGeometryType, "name");
  const bool single = stateItem<bool>(state[2], kGeometryType, "kind");
  const auto list = stateItem<py::list>(state[3], kGeometryType, "blocks");
  if (single && list.size() == 1 && py::isinstance<ClosedMesh>(list[0]))
    return held(CollisionGeometry::closed(list[0].cast<ClosedHolder>()));
  const auto blocks = stateItem<std::vector<BlockHolder>>(state[3], kGeometryType, "blocks");
  const RealArray poses = realArray(state[4], "poses");
  if (poses.ndim() != 3 || poses.shape(0) != static_cast<py::ssize_t>(blocks.size()) ||
      poses.shape(1) != 4 || poses.shape(2) != 4 || (single && blocks.size() != 1))
    throw py::value_error(std::string(kGeometryType) +
                          ": the pickled state's poses are not one 4 x 4 matrix per block");
  std::vector<BlockPart> parts;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    parts.push_back({blocks[i], rigidMotionFrom(poses.data() + 16 * i, [i] {
                       return "poses[" + std::to_string(i) + "]";
                     })});
  if (single)
    return held(CollisionGeometry::single(parts.front().block));
  return held(CollisionGeometry::compound(std::move(parts), std::move(name)));
}

// Shapes are immutable: a copy, deep or not, is the shape itself.
py::object itself(const py::object& self, const py::args&) {
  return self;
}

void bindConvexBlock(py::module_& m) {
  py::class_<ConvexBlock, BlockHolder>(
      m, "ConvexBlock",
      "A closed convex block, validated when made (recode.MeshError names the problem).")
      .def_static("from_arrays", &blockFromArrays, py::arg("vertices"), py::arg("faces"),
                  py::arg("name") = "block",
                  "A block from an (n, 3) array of vertices and an (m, 3) array of vertex "
                  "indices, counter-clockwise seen from outside. `name` starts error messages.")
      .def_static("from_file", &blockFromFile, py::arg("path"),
                  "A block from an OBJ or OFF file, named by its path.")
      .def_static("from_hull", &blockFromHull, py::arg("points"), py::arg("name") = "hull",
                  "The convex hull of an (n, 3) array of points (exact; extreme points only). "
                  "Fewer than 4 points, or all on one line or plane, raise recode.MeshError.")
      .def_static(
          "from_file_hull", &blockFromFileHull, py::arg("path"),
          "The convex hull of all vertices of an OBJ or OFF file, for collision meshes that "
          "are convex in shape but not a clean closed surface.")
      .def_property_readonly("name", &ConvexBlock::name)
      .def_property_readonly(
          "vertices",
          [](const py::object& self) {
            return pointsView(self.cast<const ConvexBlock&>().mesh().vertices, self);
          },
          "(n, 3) float64, read-only")
      .def_property_readonly("faces", &facesOf<ConvexBlock>,
                             "(m, 3) uint32 vertex indices (a copy)")
      .def(py::pickle(&shapeState<ConvexBlock>, &blockFromState))
      .def("__copy__", &itself)
      .def("__deepcopy__", &itself)
      .def("__repr__", [](const ConvexBlock& b) {
        return "<recode.ConvexBlock '" + b.name() + "': " + std::to_string(b.mesh().vertexCount()) +
               " vertices, " + std::to_string(b.mesh().triangleCount()) + " triangles>";
      });
}

void bindClosedMesh(py::module_& m) {
  py::class_<ClosedMesh, ClosedHolder>(
      m, "ClosedMesh",
      "A closed mesh of any shape (a torus, a bowl, a hollow part), validated when made "
      "(recode.MeshError names the rule broken); its pairs are decided by the layered pair.")
      .def_static("from_arrays", &closedFromArrays, py::arg("vertices"), py::arg("faces"),
                  py::arg("name") = "mesh",
                  "A closed mesh from an (n, 3) array of vertices and an (m, 3) array of vertex "
                  "indices, counter-clockwise seen from outside the solid (a cavity's wall faces "
                  "into the cavity). `name` starts error messages.")
      .def_static("from_file", &closedFromFile, py::arg("path"),
                  "A closed mesh from an OBJ, OFF, STL or PLY file, named by its path.")
      .def_property_readonly("name", &ClosedMesh::name)
      .def_property_readonly(
          "vertices",
          [](const py::object& self) {
            return pointsView(self.cast<const ClosedMesh&>().mesh().vertices, self);
          },
          "(n, 3) float64, read-only")
      .def_property_readonly("faces", &facesOf<ClosedMesh>, "(m, 3) uint32 vertex indices (a copy)")
      .def(py::pickle(&shapeState<ClosedMesh>, &closedFromState))
      .def("__copy__", &itself)
      .def("__deepcopy__", &itself)
      .def("__repr__", [](const ClosedMesh& c) {
        return "<recode.ClosedMesh '" + c.name() + "': " + std::to_string(c.mesh().vertexCount()) +
               " vertices, " + std::to_string(c.mesh().triangleCount()) + " triangles>";
      });
}

// The primitive solids of recode/geometry/generators.hpp as ready-made blocks.
void bindSolids(py::module_& m) {
  m.def(
      "torus",
      [](double radius, double tubeRadius, int segments, int rings, std::string name) {
        return held(
            ClosedMesh::fromMesh(core::makeTorus(radius, tubeRadius, segments, rings), name));
      },
      py::arg("radius"), py::arg("tube_radius"), py::arg("segments") = 48, py::arg("rings") = 24,
      py::arg("name") = "torus",
      "A torus about the z axis (a ClosedMesh): the tube's centre circle of `radius` in z = 0, "
      "the tube of `tube_radius` (less than radius).");
  m.def(
      "cone",
      [](double radius, double height, int segments, std::string name) {
        return held(ConvexBlock::fromMesh(core::makeCone(radius, height, segments), name));
      },
      py::arg("radius"), py::arg("height"), py::arg("segments") = 32, py::arg("name") = "cone",
      "A cone: base disc of `radius` in z = 0 centred at the origin, apex at (0, 0, height).");
  m.def(
      "cylinder",
      [](double radius, double height, int segments, std::string name) {
        return held(ConvexBlock::fromMesh(core::makeCylinder(radius, height, segments), name));
      },
      py::arg("radius"), py::arg("height"), py::arg("segments") = 32, py::arg("name") = "cylinder",
      "A cylinder along z from z = 0 to z = height.");
  m.def(
      "box",
      [](double hx, double hy, double hz, std::string name) {
        return held(ConvexBlock::fromMesh(core::makeBox(hx, hy, hz), name));
      },
      py::arg("hx"), py::arg("hy"), py::arg("hz"), py::arg("name") = "box",
      "An axis-aligned box centred at the origin with half extents hx, hy, hz.");
  m.def(
      "sphere",
      [](double radius, int segments, int rings, std::string name) {
        return held(ConvexBlock::fromMesh(core::makeSphere(radius, segments, rings), name));
      },
      py::arg("radius"), py::arg("segments") = 32, py::arg("rings") = 16,
      py::arg("name") = "sphere", "A tessellated sphere centred at the origin.");
}

void bindCollisionGeometry(py::module_& m) {
  py::class_<CollisionGeometry, GeometryHolder>(
      m, "CollisionGeometry",
      "An object's shape: one or several convex blocks fixed together, or one closed mesh; "
      "shared by objects.")
      .def_static(
          "single", [](const BlockHolder& block) { return held(CollisionGeometry::single(block)); },
          py::arg("block"))
      .def_static("compound", &compoundFrom, py::arg("parts"), py::arg("name") = "compound",
                  "Blocks, each a ConvexBlock or a (ConvexBlock, 4 x 4 pose in the object) tuple; "
                  "results name blocks by their index here.")
      .def_static("from_obj_groups", &geometryFromObjGroups, py::arg("path"),
                  py::arg("hull") = false,
                  "One block per object or group of an OBJ file (`o convex_0`, ... as convex "
                  "decompositions write them), each validated or, with hull=True, hulled.")
      .def_static(
          "closed", [](const ClosedHolder& mesh) { return held(CollisionGeometry::closed(mesh)); },
          py::arg("mesh"), "A closed mesh as an object's whole shape (block 0 in results).")
      .def_property_readonly(
          "closed_mesh",
          [](const CollisionGeometry& g) -> std::optional<ClosedHolder> {
            if (!g.isClosed())
              return std::nullopt;
            return held(g.closedMesh());
          },
          "The ClosedMesh of a geometry made by closed(); None for convex blocks.")
      .def_property_readonly("block_count", &CollisionGeometry::blockCount)
      .def("__len__", &CollisionGeometry::blockCount)
      .def(
          "block",
          [](const CollisionGeometry& g, std::size_t i) { return held(partAt(g, i).block); },
          py::arg("index"))
      .def(
          "block_pose",
          [](const CollisionGeometry& g, std::size_t i) { return matrixOf(partAt(g, i).pose); },
          py::arg("index"), "Block `index`'s pose in the object, 4 x 4.")
      .def(py::pickle(&geometryState, &geometryFromState))
      .def("__copy__", &itself)
      .def("__deepcopy__", &itself);
}

}  // namespace

void bindGeometry(py::module_& m) {
  bindConvexBlock(m);
  bindClosedMesh(m);
  bindSolids(m);
  bindCollisionGeometry(m);
}

}  // namespace recode::python
