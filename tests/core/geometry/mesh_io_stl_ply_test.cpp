// The STL and PLY readers: meshes written here in binary and ASCII STL and in ASCII and binary
// PLY read back as written (STL corners welded exactly, nothing else changed); broken files give
// the file, the line where there is one, and the rule; headers that claim more than the file
// holds fail before anything is allocated.

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "core_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_io.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using recode::core::test::meshErrorMessage;
using recode::core::test::TempDir;

namespace {

// A mesh whose coordinates are floats (what binary STL and float PLY hold): multiples of 2^-10.
TriangleMesh floatSphere() {
  TriangleMesh mesh = makeSphere(1.0, 12, 6);
  for (Eigen::Vector3d& p : mesh.vertices) {
    p = (p * 1024.0).array().round() / 1024.0;
  }
  return mesh;
}

void appendFloat(std::string& out, float value, bool bigEndian = false) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  for (int k = 0; k < 4; ++k) {
    const int shift = bigEndian ? 8 * (3 - k) : 8 * k;
    out += static_cast<char>((bits >> shift) & 0xff);
  }
}

void appendUint32(std::string& out, std::uint32_t value, bool bigEndian = false) {
  appendFloat(out, std::bit_cast<float>(value), bigEndian);
}

std::string binaryStl(const TriangleMesh& mesh) {
  std::string out(80, ' ');
  out.replace(0, 11, "solid named");  // a binary header may start with "solid"
  appendUint32(out, static_cast<std::uint32_t>(mesh.triangleCount()));
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      appendFloat(out, 0.0f);  // the normal, ignored
    }
    for (const VertexIndex v : t) {
      for (int axis = 0; axis < 3; ++axis) {
        appendFloat(out, static_cast<float>(mesh.vertices[v][axis]));
      }
    }
    out += std::string(2, '\0');
  }
  return out;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string asciiStl(const TriangleMesh& mesh) {
  std::string out = "solid sphere\n";
  for (const Triangle& t : mesh.triangles) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (const VertexIndex v : t) {
      const Eigen::Vector3d& p = mesh.vertices[v];
      out += "      vertex " + number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid sphere\n";
}

std::string plyHeader(const char* format, std::size_t vertices, std::size_t faces,
                      const char* coordinateType = "float") {
  return std::string("ply\nformat ") + format +
         " 1.0\ncomment written by the test\nelement vertex " + std::to_string(vertices) +
         "\nproperty " + coordinateType + " x\nproperty " + coordinateType + " y\nproperty " +
         coordinateType + " z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string asciiPly(const TriangleMesh& mesh) {
  std::string out = plyHeader("ascii", mesh.vertexCount(), mesh.triangleCount());
  for (const Eigen::Vector3d& p : mesh.vertices) {
    out += number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + "\n";
  }
  for (const Triangle& t : mesh.triangles) {
    out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
           "\n";
  }
  return out;
}

std::string binaryPly(const TriangleMesh& mesh, bool bigEndian) {
  std::string out = plyHeader(bigEndian ? "binary_big_endian" : "binary_little_endian",
                              mesh.vertexCount(), mesh.triangleCount());
  for (const Eigen::Vector3d& p : mesh.vertices) {
    for (int axis = 0; axis < 3; ++axis) {
      appendFloat(out, static_cast<float>(p[axis]), bigEndian);
    }
  }
  for (const Triangle& t : mesh.triangles) {
    out += static_cast<char>(3);
    for (const VertexIndex v : t) {
      appendUint32(out, v, bigEndian);
    }
  }
  return out;
}

// The read mesh has the original's triangles in order, each with the same corners in the same
// order, and one vertex per distinct position (the welding found every shared corner).
void checkSameSurface(const TriangleMesh& read, const TriangleMesh& original) {
  REQUIRE(read.triangleCount() == original.triangleCount());
  CHECK(read.vertexCount() == original.vertexCount());
  for (std::size_t t = 0; t < original.triangleCount(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(read.vertices[read.triangles[t][k]] == original.vertices[original.triangles[t][k]]);
    }
  }
}

#if RECODE_HAVE_ASSIMP
constexpr bool kHavePly = true;
#else
constexpr bool kHavePly = false;
#endif

}  // namespace

TEST_CASE("STL: binary and ASCII files read back as written", "[mesh_io][stl]") {
  const TempDir dir;
  const TriangleMesh sphere = floatSphere();
  const TriangleMesh binary = readStl(dir.write("sphere_binary.stl", binaryStl(sphere)));
  checkSameSurface(binary, sphere);
  const TriangleMesh ascii = readStl(dir.write("sphere_ascii.stl", asciiStl(sphere)));
  checkSameSurface(ascii, sphere);
  CHECK(ascii.vertices == binary.vertices);
  CHECK(ascii.triangles == binary.triangles);
  // Vertices are numbered in order of first appearance.
  CHECK(binary.triangles[0] == Triangle{0, 1, 2});
  // ASCII coordinates are doubles, correctly rounded, as OBJ and OFF read them.
  const TriangleMesh doubles = makeSphere(0.1, 8, 4);
  const TriangleMesh asciiDoubles = readStl(dir.write("doubles.stl", asciiStl(doubles)));
  checkSameSurface(asciiDoubles, doubles);
  // readMesh picks the reader by extension, ignoring case; several solids may follow each other.
  const auto twice = dir.write("TWICE.STL", asciiStl(sphere) + "\n" + asciiStl(sphere));
  CHECK(readMesh(twice).triangleCount() == 2 * sphere.triangleCount());
  CHECK(readMesh(twice).vertexCount() == sphere.vertexCount());
}

TEST_CASE("STL: only exactly equal corners are welded", "[mesh_io][stl]") {
  const TempDir dir;
  const float one = 1.0f;
  const float nextToOne = std::nextafter(one, 2.0f);
  auto facet = [](const std::string& a, const std::string& b, const std::string& c) {
    return "facet normal 0 0 1\nouter loop\nvertex " + a + "\nvertex " + b + "\nvertex " + c +
           "\nendloop\nendfacet\n";
  };
  // Corner (1, 0, 0) again, one float ulp away, and -0 for 0.
  const std::string ascii = "solid w\n" + facet("0 0 0", "1 0 0", "0 1 0") +
                            facet("-0 0 0", "0 1 0", "0 0 1") +
                            facet(number(nextToOne) + " 0 0", "0 0 1", "0 1 0") + "endsolid\n";
  const TriangleMesh mesh = readStl(dir.write("weld.stl", ascii));
  CHECK(mesh.vertexCount() == 5);
  CHECK(mesh.triangles == std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {4, 3, 2}});
  CHECK(mesh.vertices[4] == Eigen::Vector3d(nextToOne, 0, 0));
  // The same in binary, and corners that differ only in the last bit of a double stay apart.
  TriangleMesh three;
  three.vertices = {{0, 0, 0}, {one, 0, 0}, {0, 1, 0}, {nextToOne, 0, 0}};
  three.triangles = {{0, 1, 2}, {3, 2, 0}};
  CHECK(readStl(dir.write("weld_binary.stl", binaryStl(three))).vertexCount() == 4);
  const std::string near = "solid w\n" + facet("0.1 0 0", "1 0 0", "0 1 0") +
                           facet(number(std::nextafter(0.1, 1.0)) + " 0 0", "0 1 0", "0 0 1") +
                           "endsolid\n";
  CHECK(readStl(dir.write("near.stl", near)).vertexCount() == 5);
}

TEST_CASE("STL: broken files give the file, the line and the rule", "[mesh_io][stl]") {
  const TempDir dir;
  auto message = [&](const std::string& contents) {
    const auto path = dir.write("bad.stl", contents);
    const std::string text = meshErrorMessage([&] { (void)readStl(path); });
    CHECK_THAT(text, StartsWith(path.string()));
    return text.substr(path.string().size());
  };
  const std::string head = "solid s\nfacet normal 0 0 1\nouter loop\n";
  CHECK(message(head + "vertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\n") ==
        ":7: facet has more than 3 vertices; an STL facet is a triangle (exactly 3)");
  CHECK(message(head + "vertex 0 0 0\nvertex 1 0 0\nendloop\n") ==
        ":6: facet has 2 vertices; an STL facet is a triangle (exactly 3)");
  CHECK(message(head + "vertex 0 0 abc\n") == ":4: invalid coordinate 'abc'");
  CHECK(message(head + "vertex 0 nan 0\n") == ":4: non-finite coordinate 'nan'");
  CHECK(message(head + "vertex 0 0\n") == ":4: expected 3 coordinates, found 2 values");
  CHECK(message("solid s\nfacet 0 0 1\n") ==
        ":2: expected 'facet normal' or 'endsolid', found 'facet'");
  CHECK(message(head + "vertex 0 0 0\n") ==
        ":4: unexpected end of file: expected 'vertex' or 'endloop'");
  CHECK(message("solid s\nendsolid s\n") == ": the file has no faces (empty mesh)");
  // A 100-byte file whose binary header claims 2^32 - 1 triangles: refused from its size.
  std::string claim(80, 'x');
  appendUint32(claim, 0xffffffffU);
  claim += std::string(16, '\0');
  CHECK(message(claim) ==
        ": not an STL file: as binary STL its header declares 4294967295 triangles, which take "
        "84 + 50 * 4294967295 = 214748364834 bytes, but the file has 100 (not an ASCII STL "
        "either: it does not start with 'solid')");
  // A binary file cut short whose header starts with "solid".
  TriangleMesh one;
  one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.triangles = {{0, 1, 2}};
  const std::string cut = binaryStl(one).substr(0, 120);
  CHECK_THAT(message(cut), Contains("declares 1 triangles, which take 84 + 50 * 1 = 134 bytes, "
                                    "but the file has 120 (not an ASCII STL either: it holds NUL "
                                    "bytes)"));
  CHECK(message("tiny") ==
        ": not an STL file: 4 bytes, too short for a binary STL (at least 84) "
        "and not starting with 'solid' as an ASCII STL does");
  one.vertices[1].x() = std::numeric_limits<double>::infinity();
  CHECK(message(binaryStl(one)) == ": triangle 0 corner 1 has a non-finite coordinate (inf, 0, 0)");
}

TEST_CASE("PLY: ASCII and binary files read back as written", "[mesh_io][ply]") {
  const TempDir dir;
  const TriangleMesh sphere = floatSphere();
  const auto ascii = dir.write("sphere_ascii.ply", asciiPly(sphere));
  const auto little = dir.write("sphere_le.ply", binaryPly(sphere, false));
  const auto big = dir.write("sphere_be.PLY", binaryPly(sphere, true));
  if (!kHavePly) {
    CHECK(meshErrorMessage([&] { (void)readPly(ascii); }) ==
          ascii.string() +
              ": this build of RECODE has no PLY reader (it was built without assimp, Debian "
              "package libassimp-dev)");
    return;
  }
  for (const auto& path : {ascii, little, big}) {
    CAPTURE(path);
    const TriangleMesh mesh = readMesh(path);
    CHECK(mesh.vertices == sphere.vertices);
    CHECK(mesh.triangles == sphere.triangles);
  }
  // Polygons are fan-triangulated, vertices kept in file order (an unused one too), and
  // coordinates rounded to float: assimp reads PLY in single precision.
  const std::string quads = plyHeader("ascii", 6, 2, "double") +
                            "0.1 0 0\n1 0 0\n1 1 0\n0 1 0\n9 9 9\n0.5 0.5 1\n"
                            "4 0 1 2 3\n3 0 1 5\n";
  const TriangleMesh read = readPly(dir.write("quads.ply", quads));
  CHECK(read.triangles == std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 1, 5}});
  CHECK(read.vertexCount() == 6);
  CHECK(read.vertices[4] == Eigen::Vector3d(9, 9, 9));
  CHECK(read.vertices[0].x() == static_cast<double>(0.1f));
}

TEST_CASE("PLY: broken files give the file, the line where there is one, and the rule",
          "[mesh_io][ply]") {
  const TempDir dir;
  auto message = [&](const std::string& contents) {
    const auto path = dir.write("bad.ply", contents);
    const std::string text = meshErrorMessage([&] { (void)readPly(path); });
    CHECK_THAT(text, StartsWith(path.string()));
    return text.substr(path.string().size());
  };
  // The header is ours to check, with or without assimp.
  CHECK(message("plyx\n") == ":1: expected the PLY magic line 'ply'");
  CHECK(message("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n") ==
        ":4: unexpected end of file: no 'end_header' line");
  CHECK(message("ply\nformat ascii 1.0\nelement vertex 3\nproperty float128 x\nend_header\n") ==
        ":4: unknown PLY property type 'float128'");
  CHECK(message("ply\nformat ascii 2.0\nend_header\n") ==
        ":2: expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
  CHECK(message("ply\nformat ascii 1.0\nproperty float x\nend_header\n") ==
        ":3: a property before any element");
  CHECK(message(plyHeader("ascii", 0, 0)) == ": the file has no faces (empty mesh)");
  // 2^32 vertices declared in a file of a few hundred bytes: refused before parsing.
  const std::string body = "0 0 0\n";
  const std::string claim = plyHeader("ascii", std::size_t{1} << 32, 1) + body;
  CHECK(message(claim) ==
        ":4: element 'vertex' declares 4294967296 records, but the 6 bytes after the header can "
        "hold at most 1");
  std::string binaryClaim = plyHeader("binary_little_endian", 3, 4000000000U);
  for (int k = 0; k < 9; ++k) {
    appendFloat(binaryClaim, 0.0f);
  }
  CHECK(message(binaryClaim) ==
        ":8: element 'face' declares 4000000000 records, but the 36 bytes after the header can "
        "hold at most 36");
  CHECK(message("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                "property float y\nend_header\n12345678") ==
        ":3: the 'vertex' element has no scalar property 'z'");
  // Only numbers, blanks and line ends in an ASCII body, and nothing after 'end_header' on its
  // line (a vertical tab there made assimp's reader run for seconds: found by the fuzzer).
  std::string afterEnd = plyHeader("ascii", 3, 1);
  afterEnd.replace(afterEnd.size() - 1, 1, "\v0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  CHECK(message(afterEnd) == ":10: expected 'end_header' alone on its line");
  CHECK(message(plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1\v 0\n3 0 1 2\n") ==
        ":13: byte 0x0b in an ASCII PLY body, which holds only numbers, spaces, tabs and line "
        "ends");
  CHECK(message(plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\xff\n") ==
        ":14: byte 0xff in an ASCII PLY body, which holds only numbers, spaces, tabs and line "
        "ends");
  if (!kHavePly) {
    return;
  }
  // What assimp reads is checked too.
  const std::string triangle = plyHeader("ascii", 3, 1);
  CHECK(message(triangle + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n") ==
        ": face 0: face index 7 out of range (3 vertices)");
  CHECK(message(triangle + "nan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
        ": vertex 0 has a non-finite coordinate (nan, 0, 0) (coordinates are read in single "
        "precision: beyond 3.4e38 is infinite)");
  CHECK(message(plyHeader("ascii", 3, 1, "double") + "1e300 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
        ": vertex 0 has a non-finite coordinate (inf, 0, 0) (coordinates are read in single "
        "precision: beyond 3.4e38 is infinite)");
  CHECK(message(triangle + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n") ==
        ": face 0 has 2 vertices, at least 3 required");
}

TEST_CASE("readMesh names the four formats for an unknown extension", "[mesh_io]") {
  const TempDir dir;
  const auto other = dir.write("part.3mf", "");
  CHECK(meshErrorMessage([&] { (void)readMesh(other); }) ==
        other.string() +
            ": unknown mesh file extension '.3mf' (expected .obj, .off, .stl or .ply)");
}
