// The OBJ reader: a line check of our own gives every malformed `v` or `f` line a message with
// its line and reads the positions with correct rounding; tinyobjloader then parses the faces
// and groups from a copy in which it sees no number but the faces' indices. docs/geometry.md
// describes what is read and lists the messages.

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <iterator>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "format.hpp"
#include "mesh_io_text.hpp"

namespace recode::core::detail {
namespace {

namespace fs = std::filesystem;

// What the line check learned: the positions of the `v` records (parsed with correct
// rounding by std::from_chars) and the vertex count of every `f` record, in file order.
// tinyobjloader keeps a face's count in an unsigned char, so a face of 256 or more vertices
// would be misread from its counts alone; these are the true ones. tinyObjText is the file as
// tinyobjloader is given it (see tinyObjRecord).
struct ObjLineSummary {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::size_t> faceSizes;
  std::string tinyObjText;
};

// A `v` line: at least three coordinates, each finite; more values (w, a colour) are
// allowed and ignored.
Eigen::Vector3d checkObjVertex(const fs::path& path, const std::vector<std::string_view>& tokens,
                               std::size_t line) {
  if (tokens.size() < 4) {
    failAt(path, line,
           "expected 3 coordinates, found " + std::to_string(tokens.size() - 1) + " values");
  }
  Eigen::Vector3d p;
  if (const std::optional<std::string> problem = parseCoordinates(tokens, 1, p)) {
    failAt(path, line, *problem);
  }
  return p;
}

// An `f` line: at least three references, each with a non-zero integer vertex index; a
// negative index must name one of the vertexCount vertices defined so far. Returns the
// largest positive index (0 if none), which can only be checked once the file has ended.
long long checkObjFace(const fs::path& path, const std::vector<std::string_view>& tokens,
                       std::size_t line, std::size_t vertexCount) {
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
  return largest;
}

// What tinyobjloader is given of each record. It never parses a number of the file: its number
// parser overflows a signed int on an exponent of ten digits (`0e2147483649`, undefined
// behaviour, and finite to the line check), so every `v` line becomes `v 0 0 0` (the positions
// come from the line check) and `vt` and `vn` lines, which RECODE does not use, are blanked
// (a face's texture or normal index beyond them is only a warning there). `f`, `o` and `g`
// are kept, and the material records it already handled harmlessly. Every other record is
// ignored by RECODE, and some are unsafe in tinyobjloader: a `vw` line converts a joint id to
// int unchecked (undefined for 1e30) and a `t` line allocates up to 8192 values of each kind
// whatever its length; they are blanked.
enum class TinyObjRecord { Kept, Placeholder, Blanked };

TinyObjRecord tinyObjRecord(std::string_view keyword) {
  if (keyword == "v")
    return TinyObjRecord::Placeholder;
  static constexpr std::string_view kKept[] = {"f", "o", "g", "usemtl", "mtllib"};
  if (keyword.front() == '#' ||
      std::find(std::begin(kKept), std::end(kKept), keyword) != std::end(kKept))
    return TinyObjRecord::Kept;
  return TinyObjRecord::Blanked;
}

// Rewrites one line of tinyobjloader's copy in place (tinyObjRecord), padded with spaces so
// that lines keep their numbers and the file its size. A `v` line that passed the line check
// holds at least 7 characters, as many as its placeholder.
void rewriteForTinyObj(std::string_view keyword, std::string::iterator at, std::size_t length) {
  static constexpr std::string_view kVertexPlaceholder = "v 0 0 0";
  switch (tinyObjRecord(keyword)) {
    case TinyObjRecord::Kept:
      return;
    case TinyObjRecord::Placeholder:
      std::fill_n(std::copy(kVertexPlaceholder.begin(), kVertexPlaceholder.end(), at),
                  length - kVertexPlaceholder.size(), ' ');
      return;
    case TinyObjRecord::Blanked:
      std::fill_n(at, length, ' ');
      return;
  }
}

// Checks every `v` and `f` line (tinyobjloader accepts malformed numbers silently, and
// reports out-of-range indices without the line) and makes tinyobjloader's copy of the text in
// the same pass. Throws MeshError on the first problem.
ObjLineSummary checkObjLines(const fs::path& path, std::string_view text) {
  ObjLineSummary summary;
  summary.tinyObjText = std::string(text);
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
    if (tokens[0] == "v") {
      summary.positions.push_back(checkObjVertex(path, tokens, line));
    } else if (tokens[0] == "f") {
      const long long largest = checkObjFace(path, tokens, line, summary.positions.size());
      if (largest > 0) {
        largestPerFace.push_back({line, largest});
      }
      summary.faceSizes.push_back(tokens.size() - 1);
    }
    // After the checks: a `v` line that passed them is long enough for its placeholder.
    rewriteForTinyObj(tokens[0], summary.tinyObjText.begin() + (raw.data() - text.data()),
                      raw.size());
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

// tinyobjloader sees every `v` line as a placeholder (tinyObjRecord): the positions come from
// the line check, and the two must have counted the same vertices.
void crossCheckVertexCount(const fs::path& path, const tinyobj::attrib_t& attrib,
                           const std::vector<Eigen::Vector3d>& positions) {
  const std::size_t vertexCount = attrib.vertices.size() / 3;
  if (vertexCount != positions.size()) {
    fail(path, "internal error: tinyobjloader read " + std::to_string(vertexCount) +
                   " vertices where the line check counted " + std::to_string(positions.size()));
  }
}

// Appends the fan triangulation of every face of one shape to triangles, walking
// tinyobjloader's indices with the line check's face sizes (its own counts wrap at 256);
// faceCount counts the faces of the file so far and must stay within the line check's count.
void appendShapeFaces(const fs::path& path, const tinyobj::shape_t& shape,
                      const std::vector<std::size_t>& faceSizes, std::size_t vertexCount,
                      std::size_t& faceCount, std::vector<Triangle>& triangles) {
  std::vector<VertexIndex> polygon;
  std::size_t offset = 0;
  for (const unsigned int wrappedSize : shape.mesh.num_face_vertices) {
    if (faceCount >= faceSizes.size() || faceSizes[faceCount] % 256 != wrappedSize) {
      fail(path, "internal error: tinyobjloader's face " + std::to_string(faceCount + 1) +
                     " does not match the line check's");
    }
    const std::size_t size = faceSizes[faceCount];
    if (offset + size > shape.mesh.indices.size()) {
      fail(path, "internal error: tinyobjloader returned too few face indices");
    }
    polygon.clear();
    for (std::size_t k = 0; k < size; ++k) {
      const int index = shape.mesh.indices[offset + k].vertex_index;
      if (index < 0 || static_cast<std::size_t>(index) >= vertexCount) {
        fail(path, "internal error: tinyobjloader returned " + outOfRange(index, vertexCount));
      }
      polygon.push_back(static_cast<VertexIndex>(index));
    }
    offset += size;
    appendFan(triangles, polygon);
    ++faceCount;
  }
}

// The file as tinyobjloader's shapes (one per `o` or `g` record that is followed by faces),
// with the line check's positions and face sizes.
struct ParsedObj {
  ObjLineSummary summary;
  std::vector<tinyobj::shape_t> shapes;
};

ParsedObj loadObj(const fs::path& path, const std::string& text) {
  ParsedObj parsed{checkObjLines(path, text), {}};
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::material_t> materials;
  std::string warnings;
  std::string errors;
  std::istringstream stream(std::move(parsed.summary.tinyObjText));
  const bool ok = tinyobj::LoadObj(&attrib, &parsed.shapes, &materials, &warnings, &errors, &stream,
                                   /*readMatFn=*/nullptr, /*triangulate=*/false,
                                   /*default_vcols_fallback=*/false);
  if (!ok || !errors.empty()) {
    failFromTinyObj(path, errors);
  }
  crossCheckVertexCount(path, attrib, parsed.summary.positions);
  return parsed;
}

void checkFaceCount(const fs::path& path, std::size_t faceCount, const ObjLineSummary& summary) {
  if (faceCount != summary.faceSizes.size()) {
    fail(path, "internal error: tinyobjloader returned " + std::to_string(faceCount) +
                   " faces where the line check counted " +
                   std::to_string(summary.faceSizes.size()));
  }
}

// A group's name as the file gives it, without surrounding blanks (tinyobjloader keeps the
// rest of an `o` line as is).
std::string groupName(const std::string& raw) {
  const auto first = std::find_if_not(raw.begin(), raw.end(), [](char c) { return isBlank(c); });
  const auto last = std::find_if_not(raw.rbegin(), raw.rend(), [](char c) { return isBlank(c); });
  if (first == raw.end())
    return "(unnamed)";
  return std::string(first, last.base());
}

}  // namespace

TriangleMesh parseObj(const fs::path& path, const std::string& text) {
  ParsedObj parsed = loadObj(path, text);
  TriangleMesh mesh;
  mesh.vertices = std::move(parsed.summary.positions);
  std::size_t faceCount = 0;
  for (const tinyobj::shape_t& shape : parsed.shapes) {
    appendShapeFaces(path, shape, parsed.summary.faceSizes, mesh.vertices.size(), faceCount,
                     mesh.triangles);
  }
  checkFaceCount(path, faceCount, parsed.summary);
  if (mesh.triangles.empty()) {
    fail(path, "the file has no faces (empty mesh)");
  }
  return mesh;
}

std::vector<MeshGroup> parseObjGroups(const fs::path& path, const std::string& text) {
  const ParsedObj parsed = loadObj(path, text);
  const std::vector<Eigen::Vector3d>& positions = parsed.summary.positions;
  // The faces of each name, in the order names first appear (a name used twice is one group).
  std::vector<std::string> names;
  std::vector<std::vector<Triangle>> faces;
  std::size_t faceCount = 0;
  for (const tinyobj::shape_t& shape : parsed.shapes) {
    const std::string name = groupName(shape.name);
    const auto it = std::find(names.begin(), names.end(), name);
    const std::size_t g = static_cast<std::size_t>(it - names.begin());
    if (it == names.end()) {
      names.push_back(name);
      faces.emplace_back();
    }
    appendShapeFaces(path, shape, parsed.summary.faceSizes, positions.size(), faceCount, faces[g]);
  }
  checkFaceCount(path, faceCount, parsed.summary);

  std::vector<MeshGroup> groups;
  std::vector<VertexIndex> local(positions.size());
  for (std::size_t g = 0; g < names.size(); ++g) {
    if (faces[g].empty())
      continue;
    // The file's vertices this group's faces use, in file order.
    MeshGroup group{names[g], {}};
    std::vector<bool> used(positions.size(), false);
    for (const Triangle& t : faces[g]) {
      for (const VertexIndex v : t)
        used[v] = true;
    }
    for (std::size_t v = 0; v < positions.size(); ++v) {
      if (used[v]) {
        local[v] = static_cast<VertexIndex>(group.mesh.vertices.size());
        group.mesh.vertices.push_back(positions[v]);
      }
    }
    for (const Triangle& t : faces[g])
      group.mesh.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
    groups.push_back(std::move(group));
  }
  if (groups.empty()) {
    fail(path, "the file has no faces (empty mesh)");
  }
  return groups;
}

}  // namespace recode::core::detail
