// OBJ and OFF readers: the sample files in data/meshes and broken files written on the fly.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core_test_support.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/geometry/validate.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;
using recode::core::test::dataFile;
using recode::core::test::meshErrorMessage;
using recode::core::test::TempDir;

namespace {

const Eigen::Vector3d kUnitCube[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};

// The quads of cube_quads.{obj,off} (0-based), fan-triangulated.
const std::vector<Triangle> kCubeTriangles = {
    {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
    {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},
};

}  // namespace

TEST_CASE("readObj: tetrahedron", "[mesh_io]") {
  const TriangleMesh mesh = readObj(dataFile("meshes/tetrahedron.obj"));
  REQUIRE(mesh.vertexCount() == 4);
  REQUIRE(mesh.triangleCount() == 4);
  CHECK(mesh.vertices[0] == Eigen::Vector3d(1, 1, 1));
  CHECK(mesh.vertices[3] == Eigen::Vector3d(-1, -1, 1));
  CHECK(mesh.triangles[1] == Triangle{1, 0, 3});
  CHECK(signedVolume(mesh) == Approx(8.0 / 3.0).epsilon(1e-15));
  CHECK_NOTHROW(validateConvexBlock(mesh, "tetrahedron.obj"));
}

TEST_CASE("readObj: negative (relative) indices", "[mesh_io]") {
  const TriangleMesh mesh = readObj(dataFile("meshes/octahedron.obj"));
  REQUIRE(mesh.vertexCount() == 6);
  REQUIRE(mesh.triangleCount() == 8);
  CHECK(mesh.triangles[0] == Triangle{0, 2, 4});
  CHECK(mesh.triangles[7] == Triangle{0, 3, 5});
  CHECK(signedVolume(mesh) == Approx(4.0 / 3.0).epsilon(1e-15));
  CHECK_NOTHROW(validateConvexBlock(mesh, "octahedron.obj"));
}

TEST_CASE("readObj: quads with texture and normal references are fan-triangulated", "[mesh_io]") {
  const TriangleMesh mesh = readObj(dataFile("meshes/cube_quads.obj"));
  REQUIRE(mesh.vertexCount() == 8);
  for (std::size_t i = 0; i < 8; ++i) {
    CHECK(mesh.vertices[i] == kUnitCube[i]);
  }
  CHECK(mesh.triangles == kCubeTriangles);
  CHECK(signedVolume(mesh) == Approx(1.0).epsilon(1e-15));
  CHECK_NOTHROW(validateConvexBlock(mesh, "cube_quads.obj"));
}

TEST_CASE("readOff: octahedron, cube with quads, pentagonal prism", "[mesh_io]") {
  const TriangleMesh octahedron = readOff(dataFile("meshes/octahedron.off"));
  CHECK(octahedron.vertexCount() == 6);
  CHECK(octahedron.triangleCount() == 8);
  CHECK(octahedron.triangles == readObj(dataFile("meshes/octahedron.obj")).triangles);
  CHECK(signedVolume(octahedron) == Approx(4.0 / 3.0).epsilon(1e-15));
  CHECK_NOTHROW(validateConvexBlock(octahedron, "octahedron.off"));

  const TriangleMesh cube = readOff(dataFile("meshes/cube_quads.off"));
  REQUIRE(cube.vertexCount() == 8);
  for (std::size_t i = 0; i < 8; ++i) {
    CHECK(cube.vertices[i] == kUnitCube[i]);
  }
  CHECK(cube.triangles == kCubeTriangles);

  // Two pentagons (3 triangles each) and five quads (2 each).
  const TriangleMesh prism = readOff(dataFile("meshes/pentagonal_prism.off"));
  CHECK(prism.vertexCount() == 10);
  REQUIRE(prism.triangleCount() == 16);
  CHECK(prism.triangles[0] == Triangle{4, 3, 2});
  CHECK(prism.triangles[1] == Triangle{4, 2, 1});
  CHECK(prism.triangles[2] == Triangle{4, 1, 0});
  CHECK(prism.triangles[6] == Triangle{0, 1, 6});
  CHECK(prism.triangles[7] == Triangle{0, 6, 5});
  CHECK(prism.vertices[1] == Eigen::Vector3d(0.309016994, 0.951056516, 0.0));
  // Regular pentagon of circumradius 1 (coordinates rounded to 1e-9) times height 1.
  const double pentagon = 2.5 * std::sin(2.0 * std::numbers::pi / 5.0);
  CHECK(signedVolume(prism) == Approx(pentagon).margin(1e-8));
  CHECK_NOTHROW(validateConvexBlock(prism, "pentagonal_prism.off"));
}

TEST_CASE("OBJ and OFF coordinates are read with correct rounding", "[mesh_io]") {
  const TempDir dir;
  const std::string coordinates = "0.3 1.2345678901234567 7e22\n";
  const auto obj = dir.write("a.obj", "v " + coordinates + "v 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto off = dir.write("a.off", "OFF\n3 1 0\n" + coordinates + "1 0 0\n0 1 0\n3 0 1 2\n");
  const Eigen::Vector3d expected(0.3, 1.2345678901234567, 7e22);
  CHECK(readObj(obj).vertices[0] == expected);
  CHECK(readOff(off).vertices[0] == expected);
  // Underflow reads as zero.
  const auto tiny = dir.write("tiny.off", "OFF\n3 1 0\n1e-999 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  CHECK(readOff(tiny).vertices[0] == Eigen::Vector3d::Zero());
}

TEST_CASE("readMesh chooses the reader by extension, ignoring case", "[mesh_io]") {
  CHECK(readMesh(dataFile("meshes/tetrahedron.obj")).triangleCount() == 4);
  CHECK(readMesh(dataFile("meshes/octahedron.off")).triangleCount() == 8);

  const TempDir dir;
  std::filesystem::copy_file(dataFile("meshes/cube_quads.off"), dir.path() / "CUBE.OFF");
  std::filesystem::copy_file(dataFile("meshes/cube_quads.obj"), dir.path() / "Cube.Obj");
  CHECK(readMesh(dir.path() / "CUBE.OFF").triangles == kCubeTriangles);
  CHECK(readMesh(dir.path() / "Cube.Obj").triangles == kCubeTriangles);

  const auto unknown = dir.write("part.3mf", "solid x\nendsolid x\n");
  CHECK_THAT(
      meshErrorMessage([&] { (void)readMesh(unknown); }),
      StartsWith(unknown.string() + ": ") &&
          Contains("unknown mesh file extension '.3mf' (expected .obj, .off, .stl or .ply)"));
  const auto bare = dir.write("mesh", "OFF\n");
  CHECK_THAT(meshErrorMessage([&] { (void)readMesh(bare); }),
             Contains("unknown mesh file extension (none)"));
}

TEST_CASE("readers report missing files and directories", "[mesh_io]") {
  const TempDir dir;
  const auto missing = dir.path() / "missing.off";
  CHECK(meshErrorMessage([&] { (void)readOff(missing); }) ==
        missing.string() + ": cannot read mesh file: file not found");
  const auto missingObj = dir.path() / "missing.obj";
  CHECK(meshErrorMessage([&] { (void)readMesh(missingObj); }) ==
        missingObj.string() + ": cannot read mesh file: file not found");
  std::filesystem::create_directory(dir.path() / "folder.obj");
  CHECK_THAT(meshErrorMessage([&] { (void)readObj(dir.path() / "folder.obj"); }),
             Contains("folder.obj: cannot read mesh file: it is a directory"));
  // A device is refused before a byte is read: /dev/zero would be read until memory runs out.
  CHECK(meshErrorMessage([&] { (void)readObj("/dev/zero"); }) ==
        "/dev/zero: cannot read mesh file: it is not a regular file (a character device)");
}

TEST_CASE("readOff: broken files give the file, the line and the problem", "[mesh_io]") {
  struct Case {
    const char* name;
    std::string contents;
    std::string where;    // expected prefix after the path: ":<line>: " or ": "
    std::string problem;  // expected to be contained in the message
  };
  const std::vector<Case> cases = {
      {"empty.off", "", ":1: ", "unexpected end of file: expected the header 'OFF'"},
      {"header.off", "# comment\nOFX\n3 1 0\n", ":2: ", "expected the header 'OFF', found 'OFX'"},
      {"counts.off", "OFF\n3\n",
       ":2: ", "expected the counts line 'numVertices numFaces [numEdges]', found 1 values"},
      {"negative_count.off", "OFF\n-3 1 0\n", ":2: ", "invalid vertex count '-3'"},
      {"bad_count.off", "OFF\n3 x 0\n", ":2: ", "invalid face count 'x'"},
      {"two_coords.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n",
       ":4: ", "expected 3 coordinates, found 2 values"},
      {"four_coords.off", "OFF\n3 1 0\n0 0 0 1\n", ":3: ", "expected 3 coordinates, found 4"},
      {"bad_coord.off", "OFF\n3 1 0\n0 0 0\n1 abc 0\n", ":4: ", "invalid coordinate 'abc'"},
      {"nan.off", "OFF\n3 1 0\n0 0 0\n\n# blank line and comment above\n1 0 nan\n",
       ":6: ", "non-finite coordinate 'nan'"},
      {"inf.off", "OFF\n3 1 0\n-inf 0 0\n", ":3: ", "non-finite coordinate '-inf'"},
      {"index.off",
       "OFF\n8 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n3 0 12 1\n",
       ":11: ", "face index 12 out of range (8 vertices)"},
      {"negative_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
       ":6: ", "face index -1 out of range (3 vertices)"},
      {"bad_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n",
       ":6: ", "invalid face index '1.5'"},
      {"small_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
       ":6: ", "face has 2 vertices, at least 3 required"},
      {"short_face.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3\n",
       ":7: ", "face declares 4 vertices but lists 3"},
      {"bad_size.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nthree 0 1 2\n",
       ":6: ", "invalid polygon size 'three'"},
      {"eof_vertices.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n\n",
       ":5: ", "unexpected end of file: expected 8 vertices, read 2"},
      {"eof_faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       ":6: ", "unexpected end of file: expected 2 faces, read 1"},
      {"trailing.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n",
       ":7: ", "unexpected content after the last face (the counts line declares 1 faces)"},
      {"no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", ": ",
       "the file has no faces (empty mesh)"},
      {"crlf.off", "OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 zero\r\n3 0 1 2\r\n",
       ":5: ", "invalid coordinate 'zero'"},
  };
  const TempDir dir;
  for (const Case& c : cases) {
    const auto path = dir.write(c.name, c.contents);
    const std::string message = meshErrorMessage([&] { (void)readOff(path); });
    CAPTURE(c.name, message);
    CHECK_THAT(message, StartsWith(path.string() + c.where));
    CHECK_THAT(message, Contains(c.problem));
  }
}

TEST_CASE("readObj: broken files give the file, the line and the problem", "[mesh_io]") {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  struct Case {
    const char* name;
    std::string contents;
    std::string where;
    std::string problem;
  };
  const std::vector<Case> cases = {
      {"two_coords.obj", "# a comment\nv 0 0 0\nv 1 2\n",
       ":3: ", "expected 3 coordinates, found 2 values"},
      {"bad_coord.obj", "v 0 0 0\nv 1 abc 3\n", ":2: ", "invalid coordinate 'abc'"},
      {"nan.obj", "v 0 0 0\n\nv nan 0 0\n", ":3: ", "non-finite coordinate 'nan'"},
      {"inf.obj", "v 0 0 1e999\n", ":1: ", "non-finite coordinate '1e999'"},
      {"underflow.obj", "v 0 0 1e-999\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n",
       ":4: ", "face index 4 out of range (3 vertices)"},  // 1e-999 reads as 0, no error
      {"index.obj", triangle + "v 1 1 0\nf 1 2 3\nf 1 2 9\n",
       ":6: ", "face index 9 out of range (4 vertices)"},
      {"forward.obj", "f 1 2 3\n" + triangle, ":1: ", ""},  // forward references are fine
      {"zero.obj", triangle + "f 1 2 0\n",
       ":4: ", "face index 0 is invalid (OBJ indices start at 1)"},
      {"relative.obj", triangle + "f -1 -2 -7\n",
       ":4: ", "face index -7 out of range (3 vertices defined so far)"},
      {"small_face.obj", triangle + "f 1 2\n", ":4: ", "face has 2 vertices, at least 3 required"},
      {"bad_ref.obj", triangle + "f 1 two 3\n", ":4: ", "invalid face vertex reference 'two'"},
      {"texcoord.obj", triangle + "vt 0 0\nf 1/0 2 3\n",
       ":5: ", "Failed parse `f' line"},  // reported by tinyobjloader, with its line
      {"no_faces.obj", triangle, ": ", "the file has no faces (empty mesh)"},
      {"empty.obj", "", ": ", "the file has no faces (empty mesh)"},
      {"crlf.obj", "v 0 0 0\r\nv 1 0 0\r\n\r\nv 0 1\r\n", ":4: ", "expected 3 coordinates"},
  };
  const TempDir dir;
  for (const Case& c : cases) {
    const auto path = dir.write(c.name, c.contents);
    const std::string message = meshErrorMessage([&] { (void)readObj(path); });
    CAPTURE(c.name, message);
    if (std::string(c.name) == "forward.obj") {
      CHECK(message.empty());
      CHECK(readObj(path).triangles == std::vector<Triangle>{{0, 1, 2}});
      continue;
    }
    CHECK_THAT(message, StartsWith(path.string() + c.where));
    CHECK_THAT(message, Contains(c.problem));
  }
}

TEST_CASE("read meshes that are not convex blocks are caught by validation", "[mesh_io]") {
  // A readable file whose faces point inward: the reader accepts it, validation names it.
  const TempDir dir;
  const auto path = dir.write("inward.off",
                              "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
                              "3 0 2 1\n3 1 3 0\n3 2 3 1\n3 0 3 2\n");
  const TriangleMesh mesh = readOff(path);
  CHECK_THAT(meshErrorMessage([&] { validateConvexBlock(mesh, path.string()); }),
             StartsWith(path.string() + ": signed volume is -2.666") &&
                 EndsWith("(must be > 0): the faces point inward"));
}

namespace {

// A prism over a regular n-gon (z = 0 and z = 1), both caps one face of n vertices, as OBJ
// (1-based) and OFF (0-based) text. Caps wind so that their normals point out.
std::string prismText(int n, bool obj) {
  std::string text;
  if (!obj) {
    text += "OFF\n";
    text += std::to_string(2 * n);
    text += ' ';
    text += std::to_string(n + 2);
    text += " 0\n";
  }
  for (int z = 0; z < 2; ++z) {
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * 3.14159265358979323846 * k / n;
      if (obj)
        text += "v ";
      text += std::to_string(std::cos(a));
      text += ' ';
      text += std::to_string(std::sin(a));
      text += ' ';
      text += std::to_string(z);
      text += '\n';
    }
  }
  const int base = obj ? 1 : 0;
  const auto face = [&](const std::vector<int>& ids) {
    if (obj)
      text += 'f';
    else
      text += std::to_string(ids.size());
    for (int id : ids) {
      text += ' ';
      text += std::to_string(id + base);
    }
    text += '\n';
  };
  std::vector<int> bottom, top;
  for (int k = 0; k < n; ++k) {
    bottom.push_back(n - 1 - k);  // clockwise seen from above: the normal points down
    top.push_back(n + k);
  }
  face(bottom);
  face(top);
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    face({k, next, n + next, n + k});
  }
  return text;
}

}  // namespace

TEST_CASE("readObj: faces of 256 or more vertices are read whole, like OFF", "[mesh_io]") {
  // tinyobjloader keeps a face's vertex count in a byte; the reader must not wrap it.
  const TempDir dir;
  for (const int n : {255, 256, 300}) {
    INFO("n = " << n);
    const TriangleMesh obj = readObj(dir.write("prism.obj", prismText(n, true)));
    const TriangleMesh off = readOff(dir.write("prism.off", prismText(n, false)));
    CHECK(obj.vertices == off.vertices);
    CHECK(obj.triangles == off.triangles);
    CHECK(obj.triangleCount() == static_cast<std::size_t>(2 * (n - 2) + 2 * n));
    CHECK_NOTHROW(validateConvexBlock(obj, "prism.obj"));
  }
}

TEST_CASE("readObj: a 259-vertex face is not taken for a triangle", "[mesh_io]") {
  // A tetrahedron whose last face lists 259 references (259 = 3 mod 256): read whole, it is
  // no closed block, and validation says so instead of accepting a tetrahedron.
  const TempDir dir;
  std::string text = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4";
  for (int k = 0; k < 257; ++k)
    text += k % 2 == 0 ? " 3" : " 2";
  text += "\n";
  const TriangleMesh mesh = readObj(dir.write("garbage.obj", text));
  CHECK(mesh.triangleCount() == 3 + 257);
  CHECK_THROWS(validateConvexBlock(mesh, "garbage.obj"));
}

TEST_CASE("readObj: records RECODE does not use are ignored, whatever they hold", "[mesh_io]") {
  // tinyobjloader rejects a negative `vw` joint id, converts a huge one to int unchecked
  // (undefined behaviour, found by the OBJ fuzzer) and allocates 8192 values for a short `t`
  // line; none of these records means anything to RECODE.
  const TempDir dir;
  const std::string tetrahedron =
      "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
  const TriangleMesh plain = readObj(dir.write("plain.obj", tetrahedron));
  const std::vector<std::string> ignored = {
      "vw 0 1e30 0.5", "vw 0 -1 0.5", "t crease 8192/8192/8192", "l 1 2 9", "p 7", "s 99999999999",
      "vp 0.5 0.5",    "curv 0 1 1 2"};
  for (const std::string& record : ignored) {
    INFO(record);
    const TriangleMesh mesh = readObj(dir.write("extra.obj", record + "\n" + tetrahedron));
    CHECK(mesh.vertices == plain.vertices);
    CHECK(mesh.triangles == plain.triangles);
  }
  // tinyobjloader's number parser overflows an int on a ten-digit exponent: it never sees the
  // numbers of `v`, `vt` or `vn` lines (an extra `v` value is ignored; 0e2147483649 is 0).
  for (const std::string record : {"vt 1e2147483649 0", "vn 0 0 1e2147483649"}) {
    INFO(record);
    const TriangleMesh mesh = readObj(dir.write("numbers.obj", tetrahedron + record + "\n"));
    CHECK(mesh.triangles == plain.triangles);
  }
  const TriangleMesh extraValue =
      readObj(dir.write("w.obj", "v 1 1 1 1e2147483649\n" + tetrahedron.substr(8)));
  CHECK(extraValue.vertices == plain.vertices);
  const TriangleMesh zero =
      readObj(dir.write("zero.obj", "v 0e2147483649 1 1\n" + tetrahedron.substr(8)));
  CHECK(zero.vertices[0] == Eigen::Vector3d(0, 1, 1));
  CHECK(zero.vertices[1] == plain.vertices[1]);

  // Blanked, not removed: a later error keeps its line number.
  const std::string message =
      meshErrorMessage([&] { (void)readObj(dir.write("late.obj", "vw 0 -1 0.5\nv 0 0\n")); });
  CHECK_THAT(message, Contains("late.obj:2: expected 3 coordinates, found 2 values"));
}
