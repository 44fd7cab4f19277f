// The PLY reader: our own check of the header (its grammar, with lines, and that every element
// the header declares can fit in the bytes that follow, so that a header claiming billions of
// vertices fails before anything is allocated), then assimp's PLY importer with no
// post-processing, then our checks of what it gave: the declared numbers of vertices and faces,
// in file order, finite coordinates, indices in range, faces of at least 3 vertices
// (fan-triangulated as OBJ and OFF faces are). docs/geometry.md describes the format as read and
// lists the messages. Without assimp (RECODE_HAVE_ASSIMP 0) the header is still checked, then
// the reader says that this build has no PLY reader.

#if RECODE_HAVE_ASSIMP
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "format.hpp"
#include "mesh_io_text.hpp"
#include "recode/io/printable.hpp"

namespace recode::core::detail {
namespace {

namespace fs = std::filesystem;

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;
  std::vector<std::string> scalars;  // names of the scalar properties
  std::string listName;              // the last list property's name, if any
  std::size_t minBytes = 0;          // the least a binary record can take
  std::size_t properties = 0;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyOffset = 0;  // first byte after "end_header\n"
};

// The size of a PLY scalar type, 0 for an unknown name.
std::size_t typeBytes(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") {
    return 1;
  }
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") {
    return 2;
  }
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") {
    return 8;
  }
  return 0;
}

std::size_t checkedType(const fs::path& path, std::size_t line, std::string_view type) {
  const std::size_t bytes = typeBytes(type);
  if (bytes == 0) {
    failAt(path, line, "unknown PLY property type " + quote(type));
  }
  return bytes;
}

// One header line (after "ply").
void readHeaderLine(const fs::path& path, const std::vector<std::string_view>& tokens,
                    std::size_t line, PlyHeader& header, bool& sawFormat) {
  const std::string_view word = tokens[0];
  if (word == "comment" || word == "obj_info") {
    return;
  }
  if (word == "format") {
    if (tokens.size() != 3 || tokens[2] != "1.0") {
      failAt(path, line, "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
    }
    if (tokens[1] == "ascii") {
      header.format = PlyFormat::Ascii;
    } else if (tokens[1] == "binary_little_endian") {
      header.format = PlyFormat::BinaryLittleEndian;
    } else if (tokens[1] == "binary_big_endian") {
      header.format = PlyFormat::BinaryBigEndian;
    } else {
      failAt(path, line, "unknown PLY format " + quote(tokens[1]));
    }
    sawFormat = true;
    return;
  }
  if (word == "element") {
    const std::optional<long long> count =
        tokens.size() == 3 ? parseInteger(tokens[2]) : std::nullopt;
    if (!count || *count < 0) {
      failAt(path, line, "expected 'element <name> <count>' with a count >= 0");
    }
    PlyElement element;
    element.name = std::string(tokens[1]);
    element.count = static_cast<std::uint64_t>(*count);
    element.line = line;
    header.elements.push_back(std::move(element));
    return;
  }
  if (word == "property") {
    if (header.elements.empty()) {
      failAt(path, line, "a property before any element");
    }
    PlyElement& element = header.elements.back();
    if (tokens.size() == 5 && tokens[1] == "list") {
      element.minBytes += checkedType(path, line, tokens[2]);  // an empty list: its count only
      (void)checkedType(path, line, tokens[3]);
      element.listName = std::string(tokens[4]);
    } else if (tokens.size() == 3) {
      element.minBytes += checkedType(path, line, tokens[1]);
      element.scalars.emplace_back(tokens[2]);
    } else {
      failAt(path, line,
             "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
    }
    ++element.properties;
    return;
  }
  failAt(path, line, "unexpected PLY header line starting with " + quote(word));
}

// Every element must fit in the body: a binary record takes at least minBytes, an ASCII one at
// least two characters per property (a digit and a separator). Checked before assimp sees the
// file, so that a count in the header cannot make it allocate beyond the file's size.
void checkElementsFit(const fs::path& path, const PlyHeader& header, std::size_t bodyBytes) {
  for (const PlyElement& element : header.elements) {
    if (element.properties == 0 && element.count > 0) {
      failAt(path, element.line, "element " + quote(element.name) + " has no properties");
    }
    const std::uint64_t perRecord =
        header.format == PlyFormat::Ascii ? 2 * element.properties : element.minBytes;
    // In ASCII the last value of the file may lack its separator: one byte of slack.
    const std::uint64_t slack = header.format == PlyFormat::Ascii ? 1 : 0;
    if (element.count > 0 && (bodyBytes + slack) / perRecord < element.count) {
      failAt(path, element.line,
             "element " + quote(element.name) + " declares " + std::to_string(element.count) +
                 " records, but the " + std::to_string(bodyBytes) +
                 " bytes after the header can hold at most " +
                 std::to_string((bodyBytes + slack) / perRecord));
    }
  }
}

const PlyElement* findElement(const PlyHeader& header, std::string_view name) {
  for (const PlyElement& element : header.elements) {
    if (element.name == name) {
      return &element;
    }
  }
  return nullptr;
}

// The vertex and face elements RECODE reads: x, y, z and a vertex_indices (or vertex_index)
// list.
void checkMeshElements(const fs::path& path, const PlyHeader& header) {
  const PlyElement* vertex = findElement(header, "vertex");
  if (vertex == nullptr) {
    fail(path, "the PLY header declares no 'vertex' element");
  }
  for (const char* axis : {"x", "y", "z"}) {
    if (std::find(vertex->scalars.begin(), vertex->scalars.end(), axis) == vertex->scalars.end()) {
      failAt(path, vertex->line,
             std::string("the 'vertex' element has no scalar property '") + axis + "'");
    }
  }
  if (vertex->count > kMaxVertices) {
    failAt(path, vertex->line,
           "vertex count " + std::to_string(vertex->count) + " exceeds the limit of " +
               std::to_string(kMaxVertices));
  }
  const PlyElement* face = findElement(header, "face");
  if (face == nullptr || face->count == 0) {
    fail(path, "the file has no faces (empty mesh)");
  }
  if (face->listName != "vertex_indices" && face->listName != "vertex_index") {
    failAt(path, face->line, "the 'face' element has no 'vertex_indices' list property");
  }
}

// An ASCII body holds numbers separated by spaces, tabs and line ends: any other byte (a
// control character, a byte of another encoding) is refused here, before assimp parses it (one
// such byte after the header made assimp's reader run for seconds). `headerLines` numbers the
// body's lines after the header's.
void checkAsciiBody(const fs::path& path, std::string_view body, std::size_t headerLines) {
  std::size_t line = headerLines + 1;
  for (const char c : body) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      ++line;
    } else if (byte < 0x20 ? (c != ' ' && c != '\t' && c != '\r') : byte > 0x7e) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", byte);
      failAt(path, line,
             std::string("byte ") + hex +
                 " in an ASCII PLY body, which holds only numbers, spaces, tabs and line ends");
    }
  }
}

PlyHeader readHeader(const fs::path& path, std::string_view data) {
  PlyHeader header;
  bool sawFormat = false;
  std::size_t pos = 0;
  std::size_t line = 0;
  while (true) {
    const std::size_t end = data.find('\n', pos);
    if (end == std::string_view::npos) {
      failAt(path, std::max<std::size_t>(line, 1), "unexpected end of file: no 'end_header' line");
    }
    std::string_view text = data.substr(pos, end - pos);
    if (!text.empty() && text.back() == '\r') {
      text.remove_suffix(1);
    }
    ++line;
    pos = end + 1;
    const std::vector<std::string_view> tokens = tokenize(text);
    if (line == 1) {
      if (tokens.size() != 1 || tokens[0] != "ply") {
        failAt(path, 1, "expected the PLY magic line 'ply'");
      }
      continue;
    }
    if (tokens.empty()) {
      continue;
    }
    if (tokens[0] == "end_header") {
      if (tokens.size() != 1) {
        failAt(path, line, "expected 'end_header' alone on its line");
      }
      break;
    }
    readHeaderLine(path, tokens, line, header, sawFormat);
  }
  if (!sawFormat) {
    failAt(path, line, "the PLY header has no 'format' line");
  }
  header.bodyOffset = pos;
  if (header.format == PlyFormat::Ascii) {
    checkAsciiBody(path, data.substr(pos), line);
  }
  checkElementsFit(path, header, data.size() - pos);
  checkMeshElements(path, header);
  return header;
}

#if RECODE_HAVE_ASSIMP

// assimp's message, made safe to print and cut short.
std::string assimpProblem(const char* message) {
  constexpr std::size_t kMaxShown = 200;
  const std::string_view text(message);
  std::string shown = recode::io::printable(text.substr(0, kMaxShown));
  if (text.size() > kMaxShown) {
    shown += "...";
  }
  return "PLY: " + shown;
}

TriangleMesh toMesh(const fs::path& path, const aiMesh& in, const PlyHeader& header) {
  const std::uint64_t vertices = findElement(header, "vertex")->count;
  const std::uint64_t faces = findElement(header, "face")->count;
  if (in.mNumVertices != vertices || in.mNumFaces != faces) {
    fail(path, "PLY: read " + std::to_string(in.mNumVertices) + " vertices and " +
                   std::to_string(in.mNumFaces) + " faces, but the header declares " +
                   std::to_string(vertices) + " and " + std::to_string(faces));
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(in.mNumVertices);
  for (unsigned v = 0; v < in.mNumVertices; ++v) {
    const aiVector3D& p = in.mVertices[v];
    const Eigen::Vector3d point(p.x, p.y, p.z);
    if (!point.allFinite()) {
      fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate " +
                     formatPoint(point) +
                     " (coordinates are read in single precision: beyond 3.4e38 is infinite)");
    }
    mesh.vertices.push_back(point);
  }
  std::vector<VertexIndex> polygon;
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices < 3) {
      fail(path, "face " + std::to_string(f) + " has " + std::to_string(face.mNumIndices) +
                     " vertices, at least 3 required");
    }
    polygon.assign(face.mIndices, face.mIndices + face.mNumIndices);
    for (const VertexIndex index : polygon) {
      if (index >= mesh.vertices.size()) {
        fail(path, "face " + std::to_string(f) + ": " +
                       outOfRange(static_cast<long long>(index), mesh.vertices.size()));
      }
    }
    appendFan(mesh.triangles, polygon);
  }
  return mesh;
}

#endif

}  // namespace

TriangleMesh parsePly(const fs::path& path, std::string_view data) {
  const PlyHeader header = readHeader(path, data);
#if RECODE_HAVE_ASSIMP
  Assimp::Importer importer;
  // No post-processing: no triangulation, welding, normals or fixes; faces as the file has them.
  const aiScene* scene = importer.ReadFileFromMemory(data.data(), data.size(), 0, "ply");
  if (scene == nullptr) {
    fail(path, assimpProblem(importer.GetErrorString()));
  }
  if (scene->mNumMeshes != 1) {
    fail(path, "PLY: read " + std::to_string(scene->mNumMeshes) + " meshes, expected one");
  }
  return toMesh(path, *scene->mMeshes[0], header);
#else
  (void)header;
  fail(path,
       "this build of RECODE has no PLY reader (it was built without assimp, Debian "
       "package libassimp-dev)");
#endif
}

}  // namespace recode::core::detail
