// The OFF reader: a header line "OFF", a counts line (possibly on the header line), then
// exactly the declared vertices and faces, read line by line so that every message can name
// its line. docs/geometry.md describes the format as read here and lists the messages.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_io_text.hpp"

namespace recode::core::detail {
namespace {

namespace fs = std::filesystem;

std::string_view stripComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

// Reads the non-blank lines of an OFF file in order; each stage of the file is a method,
// and the stage decides what the next line must be.
class OffReader {
 public:
  explicit OffReader(const fs::path& path) : path_(path) {}

  // One line's tokens (comments stripped, at least one token).
  void readLine(const std::vector<std::string_view>& tokens, std::size_t line) {
    switch (stage_) {
      case Stage::Header:
        readHeader(tokens, line);
        return;
      case Stage::Counts:
        readCounts(tokens, 0, line);
        return;
      case Stage::Vertices:
        readVertex(tokens, line);
        return;
      case Stage::Faces:
        readFace(tokens, line);
        return;
      case Stage::Done:
        failAt(path_, line,
               "unexpected content after the last face (the counts line declares " +
                   std::to_string(faceCount_) + " faces)");
    }
  }

  // The mesh, once the file has ended after lineCount lines; the file must have ended
  // after its last face.
  TriangleMesh finish(std::size_t lineCount) {
    const std::size_t lastLine = std::max<std::size_t>(lineCount, 1);
    switch (stage_) {
      case Stage::Header:
        failAt(path_, lastLine, "unexpected end of file: expected the header 'OFF'");
      case Stage::Counts:
        failAt(path_, lastLine, "unexpected end of file: expected the counts line");
      case Stage::Vertices:
        failAt(path_, lastLine,
               "unexpected end of file: expected " + std::to_string(vertexCount_) +
                   " vertices, read " + std::to_string(mesh_.vertices.size()));
      case Stage::Faces:
        failAt(path_, lastLine,
               "unexpected end of file: expected " + std::to_string(faceCount_) + " faces, read " +
                   std::to_string(facesRead_));
      case Stage::Done:
        break;
    }
    if (mesh_.triangles.empty()) {
      fail(path_, "the file has no faces (empty mesh)");
    }
    return std::move(mesh_);
  }

 private:
  enum class Stage { Header, Counts, Vertices, Faces, Done };

  // "OFF", optionally followed by the counts on the same line.
  void readHeader(const std::vector<std::string_view>& tokens, std::size_t line) {
    if (tokens[0] != "OFF") {
      failAt(path_, line, "expected the header 'OFF', found " + quote(tokens[0]));
    }
    if (tokens.size() > 1) {
      readCounts(tokens, 1, line);
    } else {
      stage_ = Stage::Counts;
    }
  }

  // "numVertices numFaces [numEdges]" from tokens[first]; the edge count is checked for
  // form only, since the faces define the edges.
  void readCounts(const std::vector<std::string_view>& tokens, std::size_t first,
                  std::size_t line) {
    const std::size_t n = tokens.size() - first;
    if (n < 2 || n > 3) {
      failAt(path_, line,
             "expected the counts line 'numVertices numFaces [numEdges]', found " +
                 std::to_string(n) + " values");
    }
    const char* names[] = {"vertex", "face", "edge"};
    long long counts[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      const std::optional<long long> value = parseInteger(tokens[first + i]);
      if (!value || *value < 0) {
        failAt(path_, line,
               std::string("invalid ") + names[i] + " count " + quote(tokens[first + i]));
      }
      counts[i] = *value;
    }
    if (static_cast<unsigned long long>(counts[0]) > kMaxVertices) {
      failAt(path_, line,
             "vertex count " + std::to_string(counts[0]) + " exceeds the limit of " +
                 std::to_string(kMaxVertices));
    }
    vertexCount_ = static_cast<std::size_t>(counts[0]);
    faceCount_ = static_cast<std::size_t>(counts[1]);
    // Reserve modestly: the counts are not trusted until the lines are there.
    constexpr std::size_t kMaxReserve = std::size_t{1} << 20;
    mesh_.vertices.reserve(std::min(vertexCount_, kMaxReserve));
    mesh_.triangles.reserve(std::min(faceCount_, kMaxReserve));
    stage_ = vertexCount_ > 0 ? Stage::Vertices : (faceCount_ > 0 ? Stage::Faces : Stage::Done);
  }

  // "x y z", exactly three finite numbers.
  void readVertex(const std::vector<std::string_view>& tokens, std::size_t line) {
    if (tokens.size() != 3) {
      failAt(path_, line,
             "expected 3 coordinates, found " + std::to_string(tokens.size()) + " values");
    }
    Eigen::Vector3d p;
    if (const std::optional<std::string> problem = parseCoordinates(tokens, 0, p)) {
      failAt(path_, line, *problem);
    }
    mesh_.vertices.push_back(p);
    if (mesh_.vertices.size() == vertexCount_) {
      stage_ = faceCount_ > 0 ? Stage::Faces : Stage::Done;
    }
  }

  // "n i0 i1 ... i(n-1)", fan-triangulated. Values after the n indices (per-face colours,
  // which some writers add) are ignored.
  void readFace(const std::vector<std::string_view>& tokens, std::size_t line) {
    const std::optional<long long> size = parseInteger(tokens[0]);
    if (!size) {
      failAt(path_, line, "invalid polygon size " + quote(tokens[0]));
    }
    if (*size < 3) {
      failAt(path_, line, "face has " + std::to_string(*size) + " vertices, at least 3 required");
    }
    if (static_cast<unsigned long long>(*size) > tokens.size() - 1) {
      failAt(path_, line,
             "face declares " + std::to_string(*size) + " vertices but lists " +
                 std::to_string(tokens.size() - 1));
    }
    polygon_.clear();
    for (std::size_t k = 1; k <= static_cast<std::size_t>(*size); ++k) {
      const std::optional<long long> index = parseInteger(tokens[k]);
      if (!index) {
        failAt(path_, line, "invalid face index " + quote(tokens[k]));
      }
      if (*index < 0 || static_cast<unsigned long long>(*index) >= vertexCount_) {
        failAt(path_, line, outOfRange(*index, vertexCount_));
      }
      polygon_.push_back(static_cast<VertexIndex>(*index));
    }
    appendFan(mesh_.triangles, polygon_);
    if (++facesRead_ == faceCount_) {
      stage_ = Stage::Done;
    }
  }

  const fs::path& path_;
  Stage stage_ = Stage::Header;
  std::size_t vertexCount_ = 0;
  std::size_t faceCount_ = 0;
  std::size_t facesRead_ = 0;
  TriangleMesh mesh_;
  std::vector<VertexIndex> polygon_;  // the current face's indices, reused across faces
};

}  // namespace

TriangleMesh parseOff(const fs::path& path, std::string_view text) {
  OffReader reader(path);
  const std::size_t lineCount = forEachLine(text, [&](std::string_view raw, std::size_t line) {
    const std::vector<std::string_view> tokens = tokenize(stripComment(raw));
    if (!tokens.empty()) {
      reader.readLine(tokens, line);
    }
  });
  return reader.finish(lineCount);
}

}  // namespace recode::core::detail
