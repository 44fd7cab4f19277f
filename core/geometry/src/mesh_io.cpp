#include "recode/geometry/mesh_io.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "format.hpp"

namespace recode::core {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& problem) {
  throw MeshError(path.string() + ": " + problem);
}

[[noreturn]] void failAt(const fs::path& path, std::size_t line, const std::string& problem) {
  throw MeshError(path.string() + ":" + std::to_string(line) + ": " + problem);
}

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

// Calls visit(lineText, lineNumber) for each line (1-based). Lines end at "\n", "\r" or
// "\r\n", as tinyobjloader counts them; the terminator is not part of the text. Returns
// the number of lines.
template <typename Visit>
std::size_t forEachLine(std::string_view text, Visit&& visit) {
  std::size_t number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = pos;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') {
      ++end;
    }
    ++number;
    visit(text.substr(pos, end - pos), number);
    if (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') {
      ++end;
    }
    pos = end + 1;
  }
  return number;
}

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\f' || c == '\v';
}

std::vector<std::string_view> tokenize(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && isBlank(line[pos])) {
      ++pos;
    }
    const std::size_t start = pos;
    while (pos < line.size() && !isBlank(line[pos])) {
      ++pos;
    }
    if (pos > start) {
      tokens.push_back(line.substr(start, pos - start));
    }
  }
  return tokens;
}

// The whole token must be a number (a leading '+' is allowed); "nan" and "inf" parse.
std::optional<double> parseDouble(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') {
    token.remove_prefix(1);
  }
  double value = 0.0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ptr != end) {
    return std::nullopt;
  }
  if (ec == std::errc::result_out_of_range) {
    // A well-formed number beyond double's range: strtod gives +-HUGE_VAL (infinity) for
    // overflow, which the caller rejects as non-finite, and 0 or a subnormal for underflow.
    const std::string copy(token);
    return std::strtod(copy.c_str(), nullptr);
  }
  if (ec != std::errc()) {
    return std::nullopt;
  }
  return value;
}

std::optional<long long> parseInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') {
    token.remove_prefix(1);
  }
  long long value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end) {
    return std::nullopt;
  }
  return value;
}

std::string quote(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  if (token.size() > kMaxShown) {
    return "'" + std::string(token.substr(0, kMaxShown)) + "...'";
  }
  return "'" + std::string(token) + "'";
}

// Parses three coordinate tokens; on error returns the problem text.
std::optional<std::string> parseCoordinates(const std::vector<std::string_view>& tokens,
                                            std::size_t first, Eigen::Vector3d& out) {
  for (int axis = 0; axis < 3; ++axis) {
    const std::string_view token = tokens[first + static_cast<std::size_t>(axis)];
    const std::optional<double> value = parseDouble(token);
    if (!value) {
      return "invalid coordinate " + quote(token);
    }
    if (!std::isfinite(*value)) {
      return "non-finite coordinate " + quote(token);
    }
    out[axis] = *value;
  }
  return std::nullopt;
}

std::string outOfRange(long long index, std::size_t vertexCount) {
  return "face index " + std::to_string(index) + " out of range (" + std::to_string(vertexCount) +
         " vertices)";
}

constexpr std::size_t kMaxVertices = std::numeric_limits<VertexIndex>::max();

// Appends the fan triangulation of a polygon (indices already validated).
void appendFan(std::vector<Triangle>& triangles, const std::vector<VertexIndex>& polygon) {
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
  }
}

// ---------------------------------------------------------------------------------------
// OFF

std::string_view stripComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

TriangleMesh parseOff(const fs::path& path, std::string_view text) {
  enum class Stage { kHeader, kCounts, kVertices, kFaces, kDone };
  Stage stage = Stage::kHeader;
  std::size_t vertexCount = 0;
  std::size_t faceCount = 0;
  std::size_t facesRead = 0;
  TriangleMesh mesh;
  std::vector<VertexIndex> polygon;

  auto readCounts = [&](const std::vector<std::string_view>& tokens, std::size_t first,
                        std::size_t line) {
    const std::size_t n = tokens.size() - first;
    if (n < 2 || n > 3) {
      failAt(path, line,
             "expected the counts line 'numVertices numFaces [numEdges]', found " +
                 std::to_string(n) + " values");
    }
    const char* names[] = {"vertex", "face", "edge"};
    long long counts[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      const std::optional<long long> value = parseInteger(tokens[first + i]);
      if (!value || *value < 0) {
        failAt(path, line,
               std::string("invalid ") + names[i] + " count " + quote(tokens[first + i]));
      }
      counts[i] = *value;
    }
    if (static_cast<unsigned long long>(counts[0]) > kMaxVertices) {
      failAt(path, line,
             "vertex count " + std::to_string(counts[0]) + " exceeds the limit of " +
                 std::to_string(kMaxVertices));
    }
    vertexCount = static_cast<std::size_t>(counts[0]);
    faceCount = static_cast<std::size_t>(counts[1]);
    // Reserve modestly: the counts are not trusted until the lines are there.
    constexpr std::size_t kMaxReserve = std::size_t{1} << 20;
    mesh.vertices.reserve(std::min(vertexCount, kMaxReserve));
    mesh.triangles.reserve(std::min(faceCount, kMaxReserve));
    stage = vertexCount > 0 ? Stage::kVertices : (faceCount > 0 ? Stage::kFaces : Stage::kDone);
  };

  const std::size_t lineCount = forEachLine(text, [&](std::string_view raw, std::size_t line) {
    const std::vector<std::string_view> tokens = tokenize(stripComment(raw));
    if (tokens.empty()) {
      return;
    }
    switch (stage) {
      case Stage::kHeader:
        if (tokens[0] != "OFF") {
          failAt(path, line, "expected the header 'OFF', found " + quote(tokens[0]));
        }
        if (tokens.size() > 1) {
          readCounts(tokens, 1, line);
        } else {
          stage = Stage::kCounts;
        }
        return;
      case Stage::kCounts:
        readCounts(tokens, 0, line);
        return;
      case Stage::kVertices: {
        if (tokens.size() != 3) {
          failAt(path, line,
                 "expected 3 coordinates, found " + std::to_string(tokens.size()) + " values");
        }
        Eigen::Vector3d p;
        if (const std::optional<std::string> problem = parseCoordinates(tokens, 0, p)) {
          failAt(path, line, *problem);
        }
        mesh.vertices.push_back(p);
        if (mesh.vertices.size() == vertexCount) {
          stage = faceCount > 0 ? Stage::kFaces : Stage::kDone;
        }
        return;
      }
      case Stage::kFaces: {
        const std::optional<long long> size = parseInteger(tokens[0]);
        if (!size) {
          failAt(path, line, "invalid polygon size " + quote(tokens[0]));
        }
        if (*size < 3) {
          failAt(path, line,
                 "face has " + std::to_string(*size) + " vertices, at least 3 required");
        }
        if (static_cast<unsigned long long>(*size) > tokens.size() - 1) {
          failAt(path, line,
                 "face declares " + std::to_string(*size) + " vertices but lists " +
                     std::to_string(tokens.size() - 1));
        }
        polygon.clear();
        for (std::size_t k = 1; k <= static_cast<std::size_t>(*size); ++k) {
          const std::optional<long long> index = parseInteger(tokens[k]);
          if (!index) {
            failAt(path, line, "invalid face index " + quote(tokens[k]));
          }
          if (*index < 0 || static_cast<unsigned long long>(*index) >= vertexCount) {
            failAt(path, line, outOfRange(*index, vertexCount));
          }
          polygon.push_back(static_cast<VertexIndex>(*index));
        }
        appendFan(mesh.triangles, polygon);
        if (++facesRead == faceCount) {
          stage = Stage::kDone;
        }
        return;
      }
      case Stage::kDone:
        failAt(path, line,
               "unexpected content after the last face (the counts line declares " +
                   std::to_string(faceCount) + " faces)");
    }
  });

  const std::size_t lastLine = std::max<std::size_t>(lineCount, 1);
  switch (stage) {
    case Stage::kHeader:
      failAt(path, lastLine, "unexpected end of file: expected the header 'OFF'");
    case Stage::kCounts:
      failAt(path, lastLine, "unexpected end of file: expected the counts line");
    case Stage::kVertices:
      failAt(path, lastLine,
             "unexpected end of file: expected " + std::to_string(vertexCount) +
                 " vertices, read " + std::to_string(mesh.vertices.size()));
    case Stage::kFaces:
      failAt(path, lastLine,
             "unexpected end of file: expected " + std::to_string(faceCount) + " faces, read " +
                 std::to_string(facesRead));
    case Stage::kDone:
      break;
  }
  if (mesh.triangles.empty()) {
    fail(path, "the file has no faces (empty mesh)");
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------
// OBJ

// What the line check learned: the positions of the `v` records (parsed with correct
// rounding by std::from_chars) and the number of `f` records.
struct ObjLineSummary {
  std::vector<Eigen::Vector3d> positions;
  std::size_t faceCount = 0;
};

// Checks every `v` and `f` line (tinyobjloader accepts malformed numbers silently, and
// reports out-of-range indices without the line). Throws MeshError on the first problem.
ObjLineSummary checkObjLines(const fs::path& path, std::string_view text) {
  ObjLineSummary summary;
  struct ForwardReference {
    std::size_t line;
    long long index;  // 1-based, positive
  };
  std::vector<ForwardReference> largestPerFace;

  forEachLine(text, [&](std::string_view raw, std::size_t line) {
    const std::vector<std::string_view> tokens = tokenize(raw);
    if (tokens.empty()) {
      return;
    }
    const std::size_t vertexCount = summary.positions.size();
    if (tokens[0] == "v") {
      if (tokens.size() < 4) {
        failAt(path, line,
               "expected 3 coordinates, found " + std::to_string(tokens.size() - 1) + " values");
      }
      Eigen::Vector3d p;
      if (const std::optional<std::string> problem = parseCoordinates(tokens, 1, p)) {
        failAt(path, line, *problem);
      }
      summary.positions.push_back(p);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) {
        failAt(path, line,
               "face has " + std::to_string(tokens.size() - 1) + " vertices, at least 3 required");
      }
      long long largest = 0;
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view ref = tokens[k];
        const std::string_view vertexPart = ref.substr(0, ref.find('/'));
        const std::optional<long long> index = parseInteger(vertexPart);
        if (!index) {
          failAt(path, line, "invalid face vertex reference " + quote(ref));
        }
        if (*index == 0) {
          failAt(path, line, "face index 0 is invalid (OBJ indices start at 1)");
        }
        if (*index < 0) {
          // Relative to the vertices defined so far: -1 is the last one.
          if (static_cast<unsigned long long>(-(*index + 1)) >= vertexCount) {
            failAt(path, line,
                   "face index " + std::to_string(*index) + " out of range (" +
                       std::to_string(vertexCount) + " vertices defined so far)");
          }
        } else {
          largest = std::max(largest, *index);
        }
      }
      if (largest > 0) {
        largestPerFace.push_back({line, largest});
      }
      ++summary.faceCount;
    }
  });

  const std::size_t vertexCount = summary.positions.size();
  for (const ForwardReference& ref : largestPerFace) {
    if (static_cast<unsigned long long>(ref.index) > vertexCount) {
      failAt(path, ref.line, outOfRange(ref.index, vertexCount));
    }
  }
  if (vertexCount > kMaxVertices) {
    fail(path, "vertex count " + std::to_string(vertexCount) + " exceeds the limit of " +
                   std::to_string(kMaxVertices));
  }
  return summary;
}

// Turns tinyobjloader's error text into our message form, using a "line N" it mentions.
[[noreturn]] void failFromTinyObj(const fs::path& path, std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())) != 0) {
    text.pop_back();
  }
  if (text.empty()) {
    text = "tinyobjloader could not parse the file";
  }
  static const std::regex kLine(R"(line:?\s*(\d+))", std::regex::icase);
  std::smatch match;
  if (std::regex_search(text, match, kLine)) {
    failAt(path, static_cast<std::size_t>(std::stoull(match[1].str())), text);
  }
  fail(path, text);
}

TriangleMesh parseObj(const fs::path& path, const std::string& text) {
  ObjLineSummary summary = checkObjLines(path, text);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings;
  std::string errors;
  std::istringstream stream(text);
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream,
                                   /*readMatFn=*/nullptr, /*triangulate=*/false,
                                   /*default_vcols_fallback=*/false);
  if (!ok || !errors.empty()) {
    failFromTinyObj(path, errors);
  }

  // tinyobjloader's number parser is not correctly rounded (it can be 1 ulp off), so the
  // positions come from the line check; tinyobjloader's values must agree with them to
  // within rounding, which confirms that both counted the same vertices.
  TriangleMesh mesh;
  const std::size_t vertexCount = attrib.vertices.size() / 3;
  if (vertexCount != summary.positions.size()) {
    fail(path, "internal error: tinyobjloader read " + std::to_string(vertexCount) +
                   " vertices where the line check counted " +
                   std::to_string(summary.positions.size()));
  }
  for (std::size_t i = 0; i < vertexCount; ++i) {
    const Eigen::Vector3d theirs(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                                 attrib.vertices[3 * i + 2]);
    const Eigen::Vector3d& ours = summary.positions[i];
    if (!((theirs - ours).cwiseAbs().array() <= 1e-12 * ours.cwiseAbs().array() + 1e-300).all()) {
      fail(path, "internal error: tinyobjloader read vertex " + std::to_string(i) + " as " +
                     detail::formatPoint(theirs) + " where the line check read " +
                     detail::formatPoint(ours));
    }
  }
  mesh.vertices = std::move(summary.positions);

  std::size_t faceCount = 0;
  std::vector<VertexIndex> polygon;
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t offset = 0;
    for (const unsigned int size : shape.mesh.num_face_vertices) {
      polygon.clear();
      for (std::size_t k = 0; k < size; ++k) {
        const int index = shape.mesh.indices[offset + k].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertexCount) {
          fail(path, "internal error: tinyobjloader returned " + outOfRange(index, vertexCount));
        }
        polygon.push_back(static_cast<VertexIndex>(index));
      }
      offset += size;
      appendFan(mesh.triangles, polygon);
      ++faceCount;
    }
  }
  if (faceCount != summary.faceCount) {
    fail(path, "internal error: tinyobjloader returned " + std::to_string(faceCount) +
                   " faces where the line check counted " + std::to_string(summary.faceCount));
  }
  if (mesh.triangles.empty()) {
    fail(path, "the file has no faces (empty mesh)");
  }
  return mesh;
}

std::string lowercaseExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

TriangleMesh readObj(const std::filesystem::path& path) {
  return parseObj(path, readWholeFile(path));
}

TriangleMesh readOff(const std::filesystem::path& path) {
  return parseOff(path, readWholeFile(path));
}

TriangleMesh readMesh(const std::filesystem::path& path) {
  const std::string ext = lowercaseExtension(path);
  if (ext == ".obj") {
    return readObj(path);
  }
  if (ext == ".off") {
    return readOff(path);
  }
  fail(path, "unknown mesh file extension " + (ext.empty() ? std::string("(none)") : quote(ext)) +
                 " (expected .obj or .off)");
}

}  // namespace recode::core
