// The mesh readers' entry points (reading the file, choosing the format) and the message
// builders declared in mesh_io_text.hpp. The formats are parsed in mesh_io_off.cpp,
// mesh_io_obj.cpp, mesh_io_stl.cpp and mesh_io_ply.cpp.

#include "recode/geometry/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "mesh_io_text.hpp"
#include "recode/io/bounded_read.hpp"
#include "recode/io/printable.hpp"

namespace recode::core {
namespace detail {

void fail(const std::filesystem::path& path, const std::string& problem) {
  throw MeshError(path.string() + ": " + problem);
}

void failAt(const std::filesystem::path& path, std::size_t line, const std::string& problem) {
  throw MeshError(path.string() + ":" + std::to_string(line) + ": " + problem);
}

// Appends piece by piece: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(...) once
// this is inlined into a caller.
std::string quote(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  std::string text;
  text += '\'';
  text += recode::io::printable(token.substr(0, kMaxShown));
  if (token.size() > kMaxShown) {
    text += "...";
  }
  text += '\'';
  return text;
}

std::string outOfRange(long long index, std::size_t vertexCount) {
  return "face index " + std::to_string(index) + " out of range (" + std::to_string(vertexCount) +
         " vertices)";
}

}  // namespace detail

namespace {

namespace fs = std::filesystem;

using detail::fail;

// Bounded: a mesh path may name /dev/zero, a FIFO or a huge file (docs/geometry.md).
std::string readWholeFile(const fs::path& path) {
  try {
    return recode::io::readBoundedFile(path, recode::io::kMaxMeshFileBytes, "mesh file");
  } catch (const recode::io::FileReadError& e) {
    fail(path, e.problem());
  }
}

std::string lowercaseExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

TriangleMesh readObj(const std::filesystem::path& path) {
  return detail::parseObj(path, readWholeFile(path));
}

std::vector<MeshGroup> readObjGroups(const std::filesystem::path& path) {
  if (lowercaseExtension(path) != ".obj") {
    fail(path, "only an OBJ file has groups (\"parts_from_groups\" needs a .obj file)");
  }
  return detail::parseObjGroups(path, readWholeFile(path));
}

TriangleMesh readOff(const std::filesystem::path& path) {
  return detail::parseOff(path, readWholeFile(path));
}

TriangleMesh readStl(const std::filesystem::path& path) {
  return detail::parseStl(path, readWholeFile(path));
}

TriangleMesh readPly(const std::filesystem::path& path) {
  return detail::parsePly(path, readWholeFile(path));
}

TriangleMesh readMesh(const std::filesystem::path& path) {
  const std::string ext = lowercaseExtension(path);
  if (ext == ".obj") {
    return readObj(path);
  }
  if (ext == ".off") {
    return readOff(path);
  }
  if (ext == ".stl") {
    return readStl(path);
  }
  if (ext == ".ply") {
    return readPly(path);
  }
  fail(path, "unknown mesh file extension " +
                 (ext.empty() ? std::string("(none)") : detail::quote(ext)) +
                 " (expected .obj, .off, .stl or .ply)");
}

}  // namespace recode::core
