// The mesh readers' entry points (reading the file, choosing the format) and the message
// builders declared in mesh_io_text.hpp. The formats are parsed in mesh_io_off.cpp and
// mesh_io_obj.cpp.

#include "recode/geometry/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "mesh_io_text.hpp"

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
  text += token.substr(0, kMaxShown);
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

std::string readWholeFile(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    fail(path, "file not found");
  }
  if (fs::is_directory(status)) {
    fail(path, "is a directory, not a mesh file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    fail(path, "cannot open file for reading");
  }
  std::ostringstream contents;
  contents << in.rdbuf();
  if (in.bad()) {
    fail(path, "error while reading the file");
  }
  return std::move(contents).str();
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

TriangleMesh readOff(const std::filesystem::path& path) {
  return detail::parseOff(path, readWholeFile(path));
}

TriangleMesh readMesh(const std::filesystem::path& path) {
  const std::string ext = lowercaseExtension(path);
  if (ext == ".obj") {
    return readObj(path);
  }
  if (ext == ".off") {
    return readOff(path);
  }
  fail(path, "unknown mesh file extension " +
                 (ext.empty() ? std::string("(none)") : detail::quote(ext)) +
                 " (expected .obj or .off)");
}

}  // namespace recode::core
